//! The 3D preview: the products' meshes in the 3D view.

use crate::view3d::{Draw, view_3d_ui};

/// The colour of patterns in the 3D view (sRGB).
pub const PATTERN_RGBA: [f32; 4] = [0.86, 0.72, 0.45, 1.0];

/// The preview panel: the selected curve's solid, or every curve's.
pub fn preview_panel_ui(app: &mut crate::TraceryApp, ui: &mut egui::Ui) {
    ui.label(egui::RichText::new("3D preview").strong());
    let ids: Vec<u64> = match app.selected {
        Some(id) => vec![id],
        None => app.doc.curves.iter().map(|c| c.id).collect(),
    };
    let products: Vec<_> = ids.iter().filter_map(|id| app.worker.output(*id)).cloned().collect();
    let draws: Vec<Draw> =
        products.iter().filter_map(|p| app.caches.view_mesh(p)).map(|mesh| Draw { mesh, rgba: PATTERN_RGBA }).collect();
    view_3d_ui(ui, "preview", app.gpu_format, &draws, None, &mut app.state.orbit);
}
