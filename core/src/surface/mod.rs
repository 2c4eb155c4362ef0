//! Patterns on 3D objects: planar patterns laid on surfaces and made solid
//! there.
//!
//! - Lamp shades: rows of pattern made along circles and wrapped onto a
//!   cylinder or a cone ([`Shade`], [`wrap_rows`]).
//! - Curves drawn on a base model ([`builtin_base`] or a mesh read with
//!   [`crate::mesh::read_mesh_file`]): checked ([`SurfaceMesh`]), the part
//!   around the picked points laid flat ([`Chart`]), a spline traced on it
//!   ([`trace`], drawn in a [`SplineDomain`]), smooth frames along it ([`Frames`]), all in [`draw_on`];
//!   then a band made along it laid on the surface ([`lay_band`]), and for
//!   carving, the model hollowed to a shell ([`hollow`]).
//! - Several such solids combined with the model once ([`assemble`]): a
//!   multi-curve lamp in one body.

mod assembly;
mod band;
mod bases;
mod chart;
mod drawn;
mod frames;
mod hollow;
mod ring_domain;
mod shade;
mod sheet;
mod split_faces;
mod surface_mesh;
mod trace;

pub use assembly::{Assembly, AssemblyError, CRUMB_MM3, Part, PartRole, assemble, assemble_products};
pub use band::{BandOnSurface, Sheet, lay_band};
pub use bases::{BASE_NAMES, builtin_base};
pub use chart::{Chart, ChartError, MIN_POINTS};
pub use drawn::{
    Drawn, DrawnError, EMBOSS_SINK_MM, SNAP_REPORT_MM, SurfaceOutput, SurfaceSettings, draw_on, object_holds_model,
};
pub use frames::Frames;
pub use hollow::{HollowError, hollow};
pub use ring_domain::SplineDomain;
pub use shade::{MAX_SHADE_MM, Shade, ShadeError};
pub use sheet::{
    CHORD_TOLERANCE_MM, RowPlace, SHEET_STEP_MM, SHEET_TOLERANCE_MM, ShadeSettings, WrapError, Wrapped, wrap_rows,
};
pub use surface_mesh::{MAX_BASE_TRIANGLES, SurfaceError, SurfaceMesh, SurfacePoint};
pub use trace::{SurfaceCurve, TraceError, trace};
