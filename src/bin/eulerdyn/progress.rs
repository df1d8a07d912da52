//! Progress on stderr for work that takes a while: a bar for runs (driven by the simulated time t / t_end) and a
//! spinner for work whose length is not known in advance.
//!
//! Progress is shown only when stderr is a terminal and the user did not pass `--quiet` (see [`wanted`]), and only
//! once the work has lasted [`REVEAL_AFTER`]: a run that finishes sooner prints nothing. It is drawn on stderr
//! only, so it never mixes with the data on stdout, and it is cleared when the work ends (or fails), so that the
//! message that follows stands alone.

use std::io::IsTerminal;
use std::sync::Mutex;
use std::sync::mpsc::{self, RecvTimeoutError, Sender};
use std::thread::JoinHandle;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// How long work runs before its progress appears.
pub const REVEAL_AFTER: Duration = Duration::from_secs(1);

/// Resolution of the bar: positions per whole (per mille), so that a run updates the bar at most 1000 times.
const RESOLUTION: u64 = 1000;

/// How often a visible bar or spinner redraws on its own (it also shows elapsed time and the estimate).
const TICK: Duration = Duration::from_millis(120);

/// The bar or spinner on the terminal now, if any, so that [`clear`] can take it off before a last message.
static SHOWN: Mutex<Option<ProgressBar>> = Mutex::new(None);

/// Clears the progress on the terminal, if any, so that a message printed next (e.g. by an interrupt handler
/// that exits the process without unwinding) starts on a clean line. Safe from any thread.
pub fn clear() {
    if let Ok(mut shown) = SHOWN.lock()
        && let Some(bar) = shown.take()
    {
        bar.finish_and_clear();
    }
}

/// Whether progress may be shown: stderr is a terminal and `--quiet` was not given.
pub fn wanted(quiet: bool) -> bool {
    !quiet && std::io::stderr().is_terminal()
}

/// A progress bar or spinner on stderr that appears only after [`REVEAL_AFTER`]; see the module documentation.
///
/// Dropping it clears it, so an early return on an error leaves a clean terminal.
pub struct Progress {
    bar: ProgressBar,
    /// Stops the thread that reveals the bar after the delay, and the thread itself.
    reveal: Option<(Sender<()>, JoinHandle<()>)>,
    /// The amount of work that is the whole (e.g. t_end in seconds); 0 for a spinner.
    total: f64,
    /// What is measured and its unit, for the message: `t` and `s` give "t = 2.5 of 10 s".
    measure: String,
    unit: String,
    /// Last position set, in `RESOLUTION` units.
    position: u64,
}

impl Progress {
    /// Progress that is never shown (with `--quiet`, or when stderr is not a terminal). Updating it costs a
    /// comparison.
    pub fn hidden() -> Self {
        Self {
            bar: ProgressBar::hidden(),
            reveal: None,
            total: 0.0,
            measure: String::new(),
            unit: String::new(),
            position: 0,
        }
    }

    /// A bar labelled `label` for work whose `measure` (in `unit`) goes from 0 to `total`, e.g. a run's simulated
    /// time `t` from 0 to t_end `s`. When `visible` is false, or `total` is not a positive finite number, it is
    /// [`Progress::hidden`].
    pub fn bar(label: &str, measure: &str, total: f64, unit: &str, visible: bool) -> Self {
        if !(visible && total.is_finite() && total > 0.0) {
            return Self::hidden();
        }
        let style = ProgressStyle::with_template(
            "{prefix} [{wide_bar:.cyan/blue}] {percent:>3}%  {msg}  ({elapsed}, about {eta} left)",
        )
        .map(|s| s.progress_chars("=> "))
        .unwrap_or_else(|_| ProgressStyle::default_bar());
        let bar = ProgressBar::with_draw_target(Some(RESOLUTION), ProgressDrawTarget::hidden())
            .with_style(style)
            .with_prefix(label.to_string())
            .with_message(format!("{measure} = 0 of {total} {unit}"));
        Self::delayed(bar, measure, total, unit, REVEAL_AFTER)
    }

    /// A spinner for work of unknown length, with a message; [`Progress::hidden`] when `visible` is false.
    pub fn spinner(label: &str, message: &str, visible: bool) -> Self {
        if !visible {
            return Self::hidden();
        }
        let style = ProgressStyle::with_template("{spinner} {prefix} {msg} ({elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner());
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden())
            .with_style(style)
            .with_prefix(label.to_string())
            .with_message(message.to_string());
        Self::delayed(bar, "", 0.0, "", REVEAL_AFTER)
    }

    /// Starts a thread that shows `bar` on stderr after `delay`, unless the work ends first.
    fn delayed(bar: ProgressBar, measure: &str, total: f64, unit: &str, delay: Duration) -> Self {
        let (stop, stopped) = mpsc::channel::<()>();
        let shown = bar.clone();
        let spawned = std::thread::Builder::new()
            .name("progress".into())
            .spawn(move || {
                if stopped.recv_timeout(delay) == Err(RecvTimeoutError::Timeout) {
                    shown.set_draw_target(ProgressDrawTarget::stderr());
                    shown.enable_steady_tick(TICK);
                    if let Ok(mut slot) = SHOWN.lock() {
                        *slot = Some(shown);
                    }
                }
            });
        Self {
            bar,
            // Without the thread (the system refused one) the work simply runs without progress.
            reveal: spawned.ok().map(|handle| (stop, handle)),
            total,
            measure: measure.to_string(),
            unit: unit.to_string(),
            position: 0,
        }
    }

    /// Records that the work has reached `done` (in the units of the bar's total, e.g. the simulated time t).
    /// Cheap: the bar changes at most [`RESOLUTION`] times over the whole.
    pub fn set(&mut self, done: f64) {
        if self.total <= 0.0 {
            return;
        }
        let fraction = (done / self.total).clamp(0.0, 1.0);
        // `as` saturates, and a NaN fraction (never produced by a run) becomes 0.
        let position = (fraction * RESOLUTION as f64) as u64;
        if position != self.position {
            self.position = position;
            self.bar.set_position(position);
            // Digits enough to see the value move by a thousandth of the total.
            let decimals = (3 - self.total.log10().floor() as i32).clamp(0, 12) as usize;
            self.bar.set_message(format!(
                "{} = {done:.decimals$} of {} {}",
                self.measure, self.total, self.unit
            ));
        }
    }

    /// Records `done` out of a whole that may have changed to `total` since the bar was made (a study plans its
    /// runs after the reference run: the first call has total 1).
    pub fn update(&mut self, done: f64, total: f64) {
        if total != self.total && total.is_finite() && total > 0.0 && self.total > 0.0 {
            self.total = total;
            // Force the next `set` to redraw with the new whole.
            self.position = u64::MAX;
        }
        self.set(done);
    }

    /// Whether the bar is drawn now (false until the delay has passed, and always false when hidden).
    #[cfg(test)]
    pub fn is_visible(&self) -> bool {
        !self.bar.is_hidden()
    }

    /// The position reached, as a fraction of the whole (0 for a spinner or a hidden bar).
    #[cfg(test)]
    pub fn fraction(&self) -> f64 {
        if self.total > 0.0 {
            self.position as f64 / RESOLUTION as f64
        } else {
            0.0
        }
    }

    /// Ends the progress and clears it from the terminal. Also done on drop.
    pub fn finish(mut self) {
        self.stop();
    }

    fn stop(&mut self) {
        if let Some((stop, handle)) = self.reveal.take() {
            // The thread may already have ended (after revealing the bar); a failed send is then expected.
            let _ = stop.send(());
            let _ = handle.join();
        }
        if let Ok(mut slot) = SHOWN.lock() {
            *slot = None;
        }
        if !self.bar.is_finished() {
            self.bar.finish_and_clear();
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.stop();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hidden_bar_takes_updates_and_stays_hidden() {
        let mut p = Progress::bar("run", "t", 10.0, "s", false);
        for k in 0..=100 {
            p.set(f64::from(k) * 0.1);
        }
        assert!(!p.is_visible());
        // Hidden progress does not track anything.
        assert_eq!(p.fraction(), 0.0);
        p.finish();
    }

    #[test]
    fn a_bar_tracks_the_fraction_and_clamps_it() {
        // Visible = true, but the reveal delay is a second and stderr of a test is not a terminal: nothing is
        // drawn; the position is still tracked.
        let mut p = Progress::bar("run", "t", 4.0, "s", true);
        p.set(1.0);
        assert_eq!(p.fraction(), 0.25);
        p.set(9.0);
        assert_eq!(p.fraction(), 1.0);
        p.set(-1.0);
        assert_eq!(p.fraction(), 0.0);
        p.set(f64::NAN);
        assert_eq!(p.fraction(), 0.0);
        p.finish();
    }

    #[test]
    fn a_bar_follows_a_total_that_grows_after_it_was_made() {
        // The accuracy study's first callback is the reference run (1 of 1); the planned runs come next. The bar
        // used to stay at 100 % of 1 for the whole study.
        let mut p = Progress::bar("accuracy", "run", 1.0, "runs", true);
        p.update(0.0, 1.0);
        p.update(1.0, 170.0);
        assert!((p.fraction() - 1.0 / 170.0).abs() < 1e-3);
        p.update(85.0, 170.0);
        assert_eq!(p.fraction(), 0.5);
        p.finish();
    }

    #[test]
    fn a_zero_or_invalid_total_gives_a_hidden_bar() {
        for total in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let mut p = Progress::bar("run", "t", total, "s", true);
            p.set(1.0);
            assert!(!p.is_visible());
            assert_eq!(p.fraction(), 0.0);
        }
    }

    #[test]
    fn a_spinner_ends_cleanly_before_its_delay() {
        let p = Progress::spinner("compare", "running both forms", true);
        assert!(!p.is_visible());
        drop(p);
    }
}
