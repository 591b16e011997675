//! Figures as SVG, written by hand (no font or plotting library), and as PNG (`png.rs`, resvg): omega against the impact
//! point, a* against the mass ratio, the paper's missing Figure 1, the velocities before and
//! after, the quantities and the energy partition along the rod, and the float stability chart.
//!
//! Curves are sampled at exact rational points through the library's solver; each exact value
//! becomes an f64 only for drawing, and the samples can be written as CSV with the exact values
//! ([`PlotData`]). Coordinates carry two decimals (no stair-stepped curves), texts are Unicode
//! (ω, ω_max with a real subscript), and labels are placed where they cover nothing. The output
//! is deterministic, so it is golden-tested.

mod along;
mod chart;
mod data;
mod describe;
mod figure1;
mod omega;
mod optimum;
#[cfg(feature = "png")]
mod png;
mod scale;
mod stability;
mod svg;

pub use along::{energy_figure, quantities_figure};
pub use data::{PlotData, Value as PlotValue};
pub use figure1::{plot_figure1, velocity_figure};
pub use omega::{mass_ratio_family, omega_figure, plot_omega};
pub use optimum::{optimum_figure, plot_optimum};
#[cfg(feature = "png")]
pub use png::{PNG_SCALE, svg_to_png};
pub use stability::plot_stability;

/// Pixel size of the charts.
const SIZE: (f64, f64) = (1060.0, 640.0);

/// Curve colours (colour-blind-safe order: blue, vermilion, green, purple, orange, sky).
const PALETTE: [&str; 6] = [
    "#0072b2", "#d55e00", "#009e73", "#7b4fa0", "#e69f00", "#56b4e9",
];

/// A drawn figure and the sampled values behind it (for `--data`).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(2, 1)).build().unwrap();
/// let fig = rodimpact::report::energy_figure(&s).unwrap();
/// assert!(fig.svg.starts_with("<svg") && fig.data.is_some());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The SVG document.
    pub svg: String,
    /// The sampled values, when the figure draws sampled curves.
    pub data: Option<PlotData>,
}
