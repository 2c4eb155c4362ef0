//! Curves the patterns run along: smoothing, arc length and frames
//! ([`Curve`]), the band-to-plane mapping ([`map_along`]), the topology of a
//! pattern laid along a curve, curves read from SVG, and the `--along`
//! specifications shared by every subcommand.

mod along;
mod band_to_plane;
mod blend_geometry;
mod corners;
mod hand_drawn;
mod parametric;
mod planar_topology;
mod rounding;
mod svg_path;

pub use along::{Along, AlongError, SVG_SPACING_MM};
pub use band_to_plane::{MAPPING_TOLERANCE_MM, PlanarPattern, map_along, map_along_within};
pub use corners::CORNER_ANGLE_DEG;
pub use hand_drawn::{DrawnStroke, Hand, STROKE_SPACING_MM, StrokeShape};
pub use parametric::{Curve, CurveCursor, CurveError};
pub use planar_topology::{planar_topology, planar_topology_of_clean};
pub use rounding::MAX_CORNER_TURN_DEG;
pub use svg_path::{SvgShape, first_path_points, svg_shapes};
