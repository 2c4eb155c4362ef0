//! Patterns on 3D objects: planar patterns laid on surfaces and made solid
//! there. Today: lamp shades, rows of pattern made along circles and wrapped
//! onto a cylinder or a cone ([`Shade`], [`wrap_rows`]).

mod shade;
mod sheet;

pub use shade::{MAX_SHADE_MM, Shade, ShadeError};
pub use sheet::{
    CHORD_TOLERANCE_MM, RowPlace, SHEET_STEP_MM, SHEET_TOLERANCE_MM, ShadeSettings, WrapError, Wrapped, wrap_rows,
};
