//! Progress of a long run on stderr: a bar on a terminal, and otherwise (stderr to a file or a
//! pipe, as under a batch scheduler) a plain line every few seconds, so that a long run is never
//! silent. Shared by the worker threads of a sweep.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Seconds between plain progress lines unless `HALFPLANE_PROGRESS_SECONDS` says otherwise.
pub const DEFAULT_INTERVAL_SECONDS: f64 = 5.0;

/// The interval between plain lines: `HALFPLANE_PROGRESS_SECONDS` (a number >= 0), or
/// [`DEFAULT_INTERVAL_SECONDS`].
fn interval() -> Duration {
    std::env::var("HALFPLANE_PROGRESS_SECONDS")
        .ok()
        .and_then(|s| s.trim().parse::<f64>().ok())
        .filter(|s| s.is_finite() && *s >= 0.0 && *s < 1e9)
        .map(Duration::from_secs_f64)
        .unwrap_or(Duration::from_secs_f64(DEFAULT_INTERVAL_SECONDS))
}

/// Progress through `total` items named `unit` (`increments`, `rows`).
#[derive(Debug)]
pub struct Progress {
    bar: Option<ProgressBar>,
    label: &'static str,
    unit: &'static str,
    total: u64,
    done: AtomicU64,
    start: Instant,
    every: Duration,
    /// When the last plain line was printed, and its count (None before the first).
    last: Mutex<(Instant, Option<u64>)>,
}

impl Progress {
    /// A bar when stderr is a terminal, plain lines otherwise.
    pub fn new(label: &'static str, unit: &'static str, total: u64) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(total);
            bar.set_style(
                // The template is a constant that parses; a plain bar would do if it did not.
                ProgressStyle::with_template(&format!(
                    "{{bar:40}} {{pos}}/{{len}} {unit} {{elapsed}} (eta {{eta}})"
                ))
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            bar
        });
        let start = Instant::now();
        Self {
            bar,
            label,
            unit,
            total,
            done: AtomicU64::new(0),
            start,
            every: interval(),
            last: Mutex::new((start, None)),
        }
    }

    /// Counts `n` more items done.
    pub fn inc(&self, n: u64) {
        let done = self.done.fetch_add(n, Ordering::Relaxed) + n;
        if let Some(bar) = &self.bar {
            bar.inc(n);
            return;
        }
        let Ok(mut last) = self.last.try_lock() else {
            return; // another thread is printing
        };
        let now = Instant::now();
        if now.duration_since(last.0) >= self.every {
            *last = (now, Some(done));
            crate::output::note(&self.line(done, now));
        }
    }

    fn line(&self, done: u64, now: Instant) -> String {
        let elapsed = now.duration_since(self.start).as_secs_f64();
        let left = match done {
            0 => String::new(),
            _ if done >= self.total => String::new(),
            _ => format!(
                ", about {} left",
                crate::limits::duration(elapsed * (self.total - done) as f64 / done as f64)
            ),
        };
        format!(
            "{}: {done}/{} {} ({:.0}%), {} elapsed{left}",
            self.label,
            self.total,
            self.unit,
            100.0 * done as f64 / self.total.max(1) as f64,
            crate::limits::duration(elapsed),
        )
    }

    /// Clears the bar, or closes the plain lines with the final count when any was printed (and
    /// the last did not already say it).
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
            return;
        }
        let done = self.done.load(Ordering::Relaxed);
        let printed = self.last.lock().map(|l| l.1).unwrap_or(None);
        if printed.is_some_and(|p| p != done) {
            crate::output::note(&self.line(done, Instant::now()));
        }
    }
}

/// Runs `work`, printing `label: running, T elapsed` on stderr every interval until it returns,
/// for a long computation with no count to report (`fatigue`, `stress` and `crack` march and
/// integrate inside the library, as do the figures of `plot` that march): a long run is never
/// silent, on a terminal or not.
pub fn while_running<T>(label: &'static str, work: impl FnOnce() -> T) -> T {
    let every = interval().max(Duration::from_millis(100));
    let start = Instant::now();
    let (done, wait) = std::sync::mpsc::channel::<()>();
    std::thread::scope(|s| {
        s.spawn(move || {
            while let Err(std::sync::mpsc::RecvTimeoutError::Timeout) = wait.recv_timeout(every) {
                let elapsed = crate::limits::duration(start.elapsed().as_secs_f64());
                crate::output::note(&format!("{label}: running, {elapsed} elapsed"));
            }
        });
        let out = work();
        // The receiver may have gone only if its thread ended, which it does only on this send.
        let _ = done.send(());
        out
    })
}
