//! `numerics::sort_f64`, `sorted_order` and `sort_by_f64_key` against the standard library's
//! stable sort with the same total-order comparison (the reference they replace at every call
//! site; exact equality: both only move values).

use pidlab::numerics::{sort_by_f64_key, sort_f64, sorted_order};

/// A deterministic sequence with repeats, signed zeros and infinities (xorshift).
fn data(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|i| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            match i % 11 {
                0 => 0.0,
                1 => -0.0,
                2 => f64::INFINITY,
                3 => f64::NEG_INFINITY,
                4 => 1.5, // repeated keys: stability matters
                _ => (s % 1000) as f64 / 7.0 - 70.0,
            }
        })
        .collect()
}

#[test]
fn sort_f64_is_the_total_order_sort() {
    for (n, seed) in [
        (0, 1),
        (1, 2),
        (2, 3),
        (19, 4),
        (20, 5),
        (21, 6),
        (500, 7),
        (3001, 8),
    ] {
        let v = data(n, seed);
        let mut a = v.clone();
        sort_f64(&mut a);
        let mut b = v.clone();
        b.sort_by(f64::total_cmp);
        let bits = |x: &[f64]| x.iter().map(|y| y.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&a), bits(&b), "n = {n}");
        // −0 before +0: the total order, not partial_cmp's "equal"
        if let Some(i) = a.iter().position(|x| *x == 0.0) {
            assert!(
                a[i].is_sign_negative() || !a.iter().any(|x| *x == 0.0 && x.is_sign_negative())
            );
        }
    }
}

#[test]
fn sort_by_key_is_stable_and_matches_sort_by() {
    for (n, seed) in [(0, 11), (1, 12), (7, 13), (64, 14), (1000, 15)] {
        let keys = data(n, seed);
        // elements: (key, original index), so stability is visible
        let v: Vec<(f64, usize)> = keys.iter().copied().zip(0..).collect();
        let mut a = v.clone();
        sort_by_f64_key(&mut a, |e| e.0);
        let mut b = v.clone();
        b.sort_by(|x, y| x.0.total_cmp(&y.0));
        assert_eq!(
            a.iter().map(|e| (e.0.to_bits(), e.1)).collect::<Vec<_>>(),
            b.iter().map(|e| (e.0.to_bits(), e.1)).collect::<Vec<_>>(),
            "n = {n}"
        );
        let order = sorted_order(&keys);
        assert_eq!(order, b.iter().map(|e| e.1).collect::<Vec<_>>());
    }
    // a non-Copy element type is moved, not cloned
    let mut s = vec![
        String::from("c"),
        String::from("a"),
        String::from("b"),
        String::from("a2"),
    ];
    sort_by_f64_key(&mut s, |x| {
        if x.starts_with('a') {
            0.0
        } else {
            x.len() as f64 + (x == "c") as u8 as f64
        }
    });
    assert_eq!(s, ["a", "a2", "b", "c"]);
}
