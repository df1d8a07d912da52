//! Where a run meets its events ([`crate::events`]): the integrated motions hand every accepted step's dense
//! output to the [`Locator`] through a [`StepWatch`]; the closed forms (`exact`) are asked at any time between two
//! rows. An event quantity is computed from the same [`Sample`] as a row, potential energy included.

use nalgebra::SVector;

use super::Stop;
use crate::events::Locator;
use crate::integrate::{
    self, Dense, IntegrateError, NoWatch, OdeSystem, Settings, Stats, StepWatch,
};
use crate::sample::Sample;
use crate::scene::Scene;

/// The row `s` with its potential energy where the scene has gravity (as `simulate::run` delivers it).
pub(super) fn with_potential(scene: &Scene, s: Sample) -> Sample {
    Sample {
        potential: scene.gravity_potential(&s.q),
        ..s
    }
}

/// A Runge–Kutta run of a scene, with its events' locator if it has any.
pub(super) struct Integration<'a, 'l, 'e> {
    pub scene: &'a Scene,
    pub settings: &'a Settings,
    pub locator: Option<&'l mut Locator<'e>>,
}

/// The watch that locates events on each step's interpolant, `row` turning a state into a row.
struct EventWatch<'s, 'l, 'e, R> {
    scene: &'s Scene,
    locator: &'l mut Locator<'e>,
    row: R,
}

impl<const N: usize, R: Fn(f64, &SVector<f64, N>) -> Sample> StepWatch<N>
    for EventWatch<'_, '_, '_, R>
{
    fn step(&mut self, solution: &Dense<N>) -> Option<f64> {
        let (scene, row) = (self.scene, &self.row);
        let at = |t: f64| with_potential(scene, row(t, &solution.at(t)));
        self.locator.span(solution.t0(), solution.t1(), at)
    }
}

impl Integration<'_, '_, '_> {
    /// Integrates `sys` from `y0` over the scene's schedule, `on_row` at every row; with events, `row(t, y)` is
    /// the row at a state of the continuous solution. No events: [`NoWatch`], the plain integration.
    pub fn integrate<const N: usize, S: OdeSystem<N>, E>(
        self,
        sys: &mut S,
        y0: SVector<f64, N>,
        on_row: impl FnMut(f64, &SVector<f64, N>) -> Result<(), Stop<E>>,
        row: impl Fn(f64, &SVector<f64, N>) -> Sample,
    ) -> Result<Stats, IntegrateError<Stop<E>>> {
        let schedule = &self.scene.schedule;
        match self.locator {
            None => {
                integrate::integrate_watched(sys, y0, schedule, self.settings, on_row, &mut NoWatch)
            }
            Some(locator) => {
                let mut watch = EventWatch {
                    scene: self.scene,
                    locator,
                    row,
                };
                integrate::integrate_watched(sys, y0, schedule, self.settings, on_row, &mut watch)
            }
        }
    }
}

/// A closed-form run (`rows` streams every row to the sink it is given) with its events located on `closed`, the
/// row at any time: before each row, the interval since the last one is searched; a stop event replaces that row
/// by the row at its time and ends the run, which then counts one evaluation per row delivered.
pub(super) fn closed_form<E>(
    locator: &mut Locator,
    closed: impl Fn(f64) -> Sample,
    mut sink: impl FnMut(&Sample) -> Result<(), Stop<E>>,
    rows: impl FnOnce(
        &mut dyn FnMut(&Sample) -> Result<(), Stop<E>>,
    ) -> Result<Stats, IntegrateError<Stop<E>>>,
) -> Result<Stats, IntegrateError<Stop<E>>> {
    let mut t_last = 0.0;
    let mut delivered = 0u64;
    let mut hooked = |s: &Sample| -> Result<(), Stop<E>> {
        if let Some(t_stop) = locator.span(t_last, s.t, &closed) {
            delivered += 1;
            sink(&closed(t_stop))?;
            return Err(Stop::Finished);
        }
        t_last = s.t;
        delivered += 1;
        sink(s)
    };
    match rows(&mut hooked) {
        Err(IntegrateError::Stopped {
            cause: Stop::Finished,
            ..
        }) => Ok(Stats {
            steps: delivered - 1,
            rejected: 0,
            evals: delivered,
        }),
        other => other,
    }
}
