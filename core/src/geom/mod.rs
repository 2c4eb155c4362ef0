//! Planar geometry shared by every mode: polygons with holes ([`Region`]),
//! rectangles, booleans (the only user of `i_overlay`), the independent
//! topology count, polyline refinement, SVG path flattening and smooth
//! outlines for output.

mod boolean;
mod bridges;
mod cdt_inside;
mod centre_line;
mod clip;
mod contacts;
mod disc;
mod fill;
pub mod flatten;
mod joined_outlines;
mod narrow_gaps;
mod needles;
mod offset;
mod polygon;
mod polyline;
mod rect;
mod resolution;
mod rings_meet;
mod sanity;
mod segment;
mod smooth_outline;
mod specks;
mod stroke;
mod topology;
mod touching;
mod trace;
mod triangle_grid;

pub use boolean::{FillRule, clip_to_rect, difference, intersection, resolve_contours, union};
pub use bridges::join_parts;
pub(crate) use cdt_inside::faces_inside;
pub use centre_line::{CentreLines, MAX_CENTRE_LINE_POINTS, centre_lines};
pub use clip::{clip_polylines, crossing_rings, ring_crossing};
pub use contacts::insert_edge_contacts;
pub use disc::{arc_step, disc};
pub use fill::fill_triangles;
pub(crate) use joined_outlines::{Outline, joined_without_union};
pub use narrow_gaps::close_narrow_gaps;
pub use needles::without_needles;
pub use offset::{OFFSET_ARC_TOLERANCE_MM, offset};
pub use polygon::{Polygon, Region, ring_contains, ring_perimeter, signed_area};
pub use polyline::{refine_mapped, refine_mapped_indexed, refine_mapped_thinned, refine_mapped_thinned_split};
pub use rect::Rect;
pub use resolution::{mean_width, without_slivers};
pub use rings_meet::{meeting_rings, rings_meet};
pub use sanity::{MIN_RING_AREA, RegionDefect};
pub use segment::{closest_on_segment, polyline_distance};
pub use smooth_outline::{OutlineSegment, SmoothOptions, SmoothRing, smooth_region, smooth_ring};
pub use specks::{MIN_PART_PX, remove_specks};
pub use stroke::{STROKE_ARC_TOLERANCE_MM, brush_stroke};
pub use topology::{PatternTopology, Topology, count_topology};
pub use touching::{separate_contacts, separate_touching, separate_touching_rings};
pub use trace::{OPAQUE_ALPHA, PixelFrame, join_corners, trace_opaque};
pub use triangle_grid::{LOCATE_SLACK, TriangleGrid, barycentric};
