//! What to simulate: the run length, the output sample interval and the step events.

use crate::error::{non_negative, positive, Error, Result};

/// A step event: `size` applied at `time`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// Time of the step (≥ 0).
    pub time: f64,
    /// Step size (0: no event).
    pub size: f64,
}

/// What to simulate.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    /// End time (> 0).
    pub t_end: f64,
    /// Output sample interval (> 0).
    pub dt: f64,
    /// Set-point step.
    pub setpoint: Step,
    /// Load step at the plant input.
    pub disturbance: Step,
    /// Settling band as a fraction (default 0.02).
    pub settling_band: f64,
}

impl Scenario {
    /// Set-point step and load step.
    pub fn steps(
        t_end: f64,
        dt: f64,
        sp_time: f64,
        sp_size: f64,
        d_time: f64,
        d_size: f64,
    ) -> Scenario {
        Scenario {
            t_end,
            dt,
            setpoint: Step {
                time: sp_time,
                size: sp_size,
            },
            disturbance: Step {
                time: d_time,
                size: d_size,
            },
            settling_band: 0.02,
        }
    }

    /// Validates the scenario; errors name `t_end`, `dt`, `setpoint.time`, ….
    pub fn validate(&self) -> Result<()> {
        positive("t_end", self.t_end)?;
        positive("dt", self.dt)?;
        if self.t_end / self.dt > 1e7 {
            return Err(Error::new(
                "dt",
                "too small for t_end: more than 10⁷ output samples",
            ));
        }
        non_negative("setpoint.time", self.setpoint.time)?;
        crate::error::finite("setpoint.size", self.setpoint.size)?;
        non_negative("disturbance.time", self.disturbance.time)?;
        crate::error::finite("disturbance.size", self.disturbance.size)?;
        if !(self.settling_band > 0.0 && self.settling_band < 1.0) {
            return Err(Error::new("settling_band", "must lie in (0, 1)"));
        }
        Ok(())
    }
}
