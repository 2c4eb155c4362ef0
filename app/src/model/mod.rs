//! The model workspace: a 3D model in the 3D view, curves picked on its
//! surface by clicking, and the vector brush's pattern along each, made as
//! a shell on the surface, embossed on the model or carved out of it; and
//! 3D texture grown over the whole model from a swatch.

mod job;
mod panel;
mod shade_panel;
mod texture;
mod view;

pub use job::{ASSEMBLY, AssemblyJob, ShadeJob, SurfaceJob};
pub use panel::{model_panel_ui, model_status_ui};
pub use texture::{TEXTURE, TextureJob, submit_texture};
pub use view::model_view_ui;
