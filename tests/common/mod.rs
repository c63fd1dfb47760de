//! Helpers shared by the integration tests (each test file includes this with `mod common;`).

/// Exact solution of y' = a·(1 − y(t − θ)) for t ≥ θ, y = 0 before (integrator k/s with delay θ
/// under P control K_p, a = k·K_p, unit set-point step at 0), by the method of steps:
/// z = 1 − y solves z'(t) = −a z(t − θ) with z ≡ 1 up to θ, so on [jθ, (j+1)θ]
/// z(t) = Σ_{i=0}^{j} (−a)^i (t − iθ)^i / i!.
pub fn integrator_p_exact(a: f64, theta: f64, t: f64) -> f64 {
    if t <= 0.0 {
        return 0.0;
    }
    let j = (t / theta).floor() as i32;
    let mut z = 0.0;
    let mut fact = 1.0;
    for i in 0..=j.max(0) {
        if i > 0 {
            fact *= i as f64;
        }
        let dt = t - i as f64 * theta;
        if dt < 0.0 {
            break;
        }
        z += (-a).powi(i) * dt.powi(i) / fact;
    }
    1.0 - z
}
