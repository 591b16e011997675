//! Axis scales: linear with "nice" steps (1, 2, 5 times a power of ten) or logarithmic by
//! decades, their ticks and tick labels (`0.01`, `0.1`, `1`, `10`, `100`, then `10^{5}`).

/// A mapping from data values to the unit interval along one axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Scale {
    /// `lo..hi`, linear.
    Linear { lo: f64, hi: f64 },
    /// `lo..hi`, both > 0, logarithmic.
    Log { lo: f64, hi: f64 },
}

/// One tick: its value, and its label if it has one (minor log ticks have none).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Tick {
    pub(crate) value: f64,
    pub(crate) label: Option<String>,
}

/// About this many labelled ticks on a linear axis.
const TARGET_TICKS: f64 = 6.0;

/// The nice step (1, 2 or 5 times a power of ten) for `span` split in about `TARGET_TICKS`.
fn nice_step(span: f64) -> Step {
    let raw = span / TARGET_TICKS;
    let power = raw.log10().floor() as i32;
    let mantissa = raw / 10f64.powi(power);
    let (nice, power) = if mantissa < 1.5 {
        (1.0, power)
    } else if mantissa < 3.5 {
        (2.0, power)
    } else if mantissa < 7.5 {
        (5.0, power)
    } else {
        (1.0, power + 1)
    };
    Step { nice, power }
}

/// A step `nice * 10^power`, multiplied without the rounding of a binary 0.1 (6 × 0.2 is 1.2,
/// not 1.2000000000000002).
#[derive(Debug, Clone, Copy)]
struct Step {
    nice: f64,
    power: i32,
}

impl Step {
    fn times(self, k: f64) -> f64 {
        if self.power >= 0 {
            k * self.nice * 10f64.powi(self.power)
        } else {
            k * self.nice / 10f64.powi(-self.power)
        }
    }
    fn size(self) -> f64 {
        self.times(1.0)
    }
}

/// `x` with the decimals that `step` needs; negatives with a true minus sign.
fn linear_label(x: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let text = format!("{:.*}", decimals, x.abs());
    if x < 0.0 && text.chars().any(|c| c.is_ascii_digit() && c != '0') {
        format!("−{text}")
    } else {
        text
    }
}

/// The label of 10^k: plain decimals from 0.001 to 10000, a power beyond.
fn decade_label(k: i32) -> String {
    match k {
        -3..=-1 => format!("0.{}1", "0".repeat((-k - 1) as usize)),
        0..=4 => format!("1{}", "0".repeat(k as usize)),
        _ => format!("10^{{{}}}", k.to_string().replace('-', "−")),
    }
}

impl Scale {
    /// A linear scale covering `lo..hi` widened to whole steps.
    pub(crate) fn linear_nice(lo: f64, hi: f64) -> Scale {
        let (lo, hi) = if hi > lo {
            (lo, hi)
        } else {
            (lo - 1.0, lo + 1.0)
        };
        let step = nice_step(hi - lo);
        Scale::Linear {
            lo: step.times((lo / step.size() + 1e-9).floor()),
            hi: step.times((hi / step.size() - 1e-9).ceil()),
        }
    }

    /// A log scale from the decade at or below `lo` to the decade at or above `hi`.
    pub(crate) fn log_decades(lo: f64, hi: f64) -> Scale {
        Scale::Log {
            lo: 10f64.powf((lo.log10() + 1e-9).floor()),
            hi: 10f64.powf((hi.log10() - 1e-9).ceil()),
        }
    }

    /// Where `x` falls, 0 at `lo` and 1 at `hi` (outside for values outside).
    pub(crate) fn fraction(&self, x: f64) -> f64 {
        match *self {
            Scale::Linear { lo, hi } => (x - lo) / (hi - lo),
            Scale::Log { lo, hi } => (x.log10() - lo.log10()) / (hi.log10() - lo.log10()),
        }
    }

    /// The range `(lo, hi)`.
    pub(crate) fn range(&self) -> (f64, f64) {
        match *self {
            Scale::Linear { lo, hi } | Scale::Log { lo, hi } => (lo, hi),
        }
    }

    /// The ticks: every nice step (linear); every decade, labelled every n-th so that at most
    /// nine are, and unlabelled 2..9 between decades when the axis spans few (log).
    pub(crate) fn ticks(&self) -> Vec<Tick> {
        match *self {
            Scale::Linear { lo, hi } => {
                let step = nice_step(hi - lo);
                let first = (lo / step.size() - 1e-9).ceil() as i64;
                let last = (hi / step.size() + 1e-9).floor() as i64;
                (first..=last)
                    .map(|k| {
                        let value = step.times(k as f64);
                        Tick {
                            value,
                            label: Some(linear_label(value, step.size())),
                        }
                    })
                    .collect()
            }
            Scale::Log { lo, hi } => {
                let (first, last) = (
                    (lo.log10() - 1e-9).ceil() as i32,
                    (hi.log10() + 1e-9).floor() as i32,
                );
                let every = ((last - first) / 8 + 1).max(1);
                let mut ticks = Vec::new();
                for k in first..=last {
                    let decade = 10f64.powi(k);
                    ticks.push(Tick {
                        value: decade,
                        label: ((k - first) % every == 0).then(|| decade_label(k)),
                    });
                    if last - first <= 6 && k < last {
                        ticks.extend((2..10).map(|j| Tick {
                            value: f64::from(j) * decade,
                            label: None,
                        }));
                    }
                }
                ticks
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(scale: Scale) -> Vec<String> {
        scale.ticks().into_iter().filter_map(|t| t.label).collect()
    }

    #[test]
    fn log_axis_labels_every_decade_plainly() {
        let scale = Scale::log_decades(0.01, 100.0);
        assert_eq!(labels(scale), ["0.01", "0.1", "1", "10", "100"]);
        // Minor ticks 2..9 in each of the 4 decades, none after the last.
        assert_eq!(scale.ticks().len(), 5 + 4 * 8);
    }

    #[test]
    fn wide_log_axes_thin_their_labels_and_write_powers() {
        let scale = Scale::log_decades(1e-1, 1e17);
        assert_eq!(
            labels(scale),
            [
                "0.1", "100", "10^{5}", "10^{8}", "10^{11}", "10^{14}", "10^{17}"
            ]
        );
    }

    #[test]
    fn linear_axis_widens_to_nice_steps() {
        let scale = Scale::linear_nice(0.0, 1.13);
        assert_eq!(scale.range(), (0.0, 1.2));
        assert_eq!(
            labels(scale),
            ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0", "1.2"]
        );
        assert_eq!(
            labels(Scale::linear_nice(-1.0, 0.5)).first().unwrap(),
            "−1.0"
        );
        assert_eq!(
            labels(Scale::linear_nice(0.0, 90.0)),
            ["0", "20", "40", "60", "80", "100"]
        );
    }

    #[test]
    fn fractions_map_the_ends_to_0_and_1() {
        let log = Scale::log_decades(0.01, 100.0);
        assert!((log.fraction(1.0) - 0.5).abs() < 1e-12);
        let lin = Scale::Linear { lo: -1.0, hi: 1.0 };
        assert_eq!(lin.fraction(0.5), 0.75);
    }
}
