//! The 3D view drawn through wgpu (lavapipe where there is no GPU): depth
//! decides what is in front, not the order of drawing; the ray under a
//! click finds the model's point that is drawn there.

use std::sync::Arc;

use egui_kittest::Harness;
use egui_kittest::wgpu::{WgpuTestRenderer, create_render_state, default_wgpu_setup};
use glam::Vec3;
use tracery::view3d::{Draw, Orbit, ViewMesh, view_3d_ui};
use tracery_core::mesh::Mesh;
use tracery_core::surface::{SurfaceMesh, builtin_base};

/// A square in the plane `y = y_mm`, `half_mm` from the axis, facing -y.
fn square(y_mm: f64, half_mm: f64) -> Mesh {
    let h = half_mm;
    Mesh {
        vertices: vec![[-h, y_mm, -h], [h, y_mm, -h], [h, y_mm, h], [-h, y_mm, h]],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    }
}

const RED: [f32; 4] = [0.9, 0.1, 0.1, 1.0];
const BLUE: [f32; 4] = [0.1, 0.2, 0.9, 1.0];

/// Renders `draws` in a 300 x 300 view looking along +y; returns the picture.
fn render(draws: Vec<Draw>, orbit: Orbit) -> image::RgbaImage {
    let state = create_render_state(default_wgpu_setup(), egui_wgpu_options());
    let format = Some(state.target_format);
    let mut harness = Harness::builder()
        .with_size(egui::vec2(300.0, 300.0))
        .renderer(WgpuTestRenderer::from_render_state(state))
        .build_ui_state(
            move |ui: &mut egui::Ui, orbit: &mut Orbit| {
                egui::CentralPanel::default().frame(egui::Frame::NONE).show(ui, |ui| {
                    view_3d_ui(ui, "test", format, &draws, None, orbit);
                });
            },
            orbit,
        );
    harness.run();
    harness.render().expect("the view renders")
}

fn egui_wgpu_options() -> eframe::egui_wgpu::RendererOptions {
    eframe::egui_wgpu::RendererOptions::PREDICTABLE
}

/// Looking straight along +y from -y.
fn front() -> Orbit {
    Orbit { yaw: 0.0, pitch: 0.0, ..Orbit::default() }
}

fn dominant(pixel: &image::Rgba<u8>) -> &'static str {
    let [r, g, b, _] = pixel.0.map(u16::from);
    if r > 2 * b.max(g) && r > 40 {
        "red"
    } else if b > 2 * r.max(g) && b > 40 {
        "blue"
    } else {
        "neither"
    }
}

#[test]
fn the_nearer_mesh_hides_the_farther_whatever_the_order() {
    // The blue square is nearer the eye (at -y) and smaller; the red one is behind it.
    let near = Arc::new(ViewMesh::new(&square(-5.0, 10.0)));
    let far = Arc::new(ViewMesh::new(&square(5.0, 20.0)));
    for order in [[0, 1], [1, 0]] {
        let draws: Vec<Draw> =
            order
                .iter()
                .map(|&k| {
                    if k == 0 { Draw { mesh: near.clone(), rgba: BLUE } } else { Draw { mesh: far.clone(), rgba: RED } }
                })
                .collect();
        let picture = render(draws, front());
        let centre = picture.get_pixel(150, 150);
        assert_eq!(dominant(centre), "blue", "drawn in order {order:?}, the centre is {centre:?}");
        // Beside the near square, the far one shows.
        let corner = picture.get_pixel(150 + 60, 150 - 60);
        assert_eq!(dominant(corner), "red", "drawn in order {order:?}, beside the near square is {corner:?}");
    }
}

/// What the picking test's view gives back.
#[derive(Default)]
struct Picked {
    orbit: Orbit,
    rect: Option<egui::Rect>,
    camera: Option<tracery::view3d::Camera>,
    ray: Option<(Vec3, Vec3)>,
}

#[test]
fn a_click_casts_the_ray_onto_the_point_drawn_there() {
    let base = builtin_base("vase").expect("the vase is built in");
    let surface = SurfaceMesh::new(base.clone()).expect("the vase is a sound mesh");
    let mesh = Arc::new(ViewMesh::new(&base));
    let draws = vec![Draw { mesh, rgba: RED }];
    let mut harness = Harness::builder().with_size(egui::vec2(400.0, 300.0)).build_ui_state(
        move |ui: &mut egui::Ui, state: &mut Picked| {
            egui::CentralPanel::default().frame(egui::Frame::NONE).show(ui, |ui| {
                let out = view_3d_ui(ui, "pick", None, &draws, None, &mut state.orbit);
                state.rect = Some(out.response.rect);
                state.camera = Some(out.camera);
                if let Some(ray) = out.clicked_ray {
                    state.ray = Some(ray);
                }
            });
        },
        Picked::default(),
    );
    harness.run();
    // A click a little off the centre, where the vase's side is.
    let at = egui::pos2(215.0, 160.0);
    harness.input_mut().events.push(egui::Event::PointerMoved(at));
    harness.run();
    for pressed in [true, false] {
        harness.input_mut().events.push(egui::Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
        harness.run();
    }
    let (origin, dir) = harness.state().ray.expect("the click gave a ray");
    let hit = surface.ray_hit(origin.as_dvec3(), dir.as_dvec3()).expect("the ray through the vase's middle hits it");
    // The hit projects back to the pixel clicked.
    let (camera, rect) = (harness.state().camera.expect("drawn"), harness.state().rect.expect("drawn"));
    let ndc = camera.project(surface.point(hit.face, hit.barycentric).as_vec3());
    let pixel = rect.center() + egui::vec2(ndc.x * rect.width(), -ndc.y * rect.height()) / 2.0;
    assert!(pixel.distance(at) < 0.5, "the picked point is drawn at {pixel:?}, the click was at {at:?}");
}
