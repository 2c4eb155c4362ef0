//! Frame time of the 3D view: a 200k-triangle mesh drawn by the app's own
//! renderer (depth buffer, 4× MSAA, offscreen, then resolved) at the size of
//! the app's central panel, on whatever adapter wgpu picks first among CPU
//! ones (Mesa's lavapipe on a machine without a GPU).
//!
//! ```sh
//! cargo bench -p tracery --bench view3d [-- --triangles N] [--size WxH] [--frames N] [--moving] [--png OUT.png]
//! ```
//! Prints the adapter, the upload time, and p50 / p95 / worst of the frame
//! time (recorded, submitted and waited for); `--moving` draws as while the
//! camera moves (no MSAA); `--png` writes the last frame.

use std::sync::Arc;
use std::time::{Duration, Instant};

use eframe::wgpu;
use egui_kittest::wgpu::{create_render_state, default_wgpu_setup};
use glam::{Vec2, Vec3};
use tracery::view3d::{Bounds, Draw, Frame3d, Orbit, Renderer3d, ViewMesh};

/// A torus of `triangles` triangles (rounded to its grid), 60 mm across.
fn torus(triangles: usize) -> ViewMesh {
    let nv = ((triangles as f64 / 5.0).sqrt().round() as usize).max(3);
    let nu = (triangles / (2 * nv)).max(3);
    let (big, small) = (22.0f32, 8.0f32);
    let mut positions = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        let u = i as f32 / nu as f32 * std::f32::consts::TAU;
        for j in 0..nv {
            let v = j as f32 / nv as f32 * std::f32::consts::TAU;
            // A ripple, so that the shading has something to show.
            let r = small * (1.0 + 0.06 * (9.0 * u).sin() * (5.0 * v).cos());
            positions.push([(big + r * v.cos()) * u.cos(), (big + r * v.cos()) * u.sin(), r * v.sin()]);
        }
    }
    let mut indices = Vec::with_capacity(nu * nv * 6);
    for i in 0..nu {
        for j in 0..nv {
            let at = |a: usize, b: usize| ((a % nu) * nv + b % nv) as u32;
            indices.extend_from_slice(&[at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            indices.extend_from_slice(&[at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    let bounds = Bounds { min: Vec3::new(-30.0, -30.0, -9.0), max: Vec3::new(30.0, 30.0, 9.0) };
    ViewMesh { positions, indices, bounds }
}

fn percentile(sorted: &[Duration], p: f64) -> Duration {
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

fn main() {
    let mut triangles = 200_000usize;
    let mut size = [960u32, 620u32];
    let mut frames = 30usize;
    let mut png: Option<String> = None;
    let mut antialias = true;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--triangles" => triangles = args.next().and_then(|s| s.parse().ok()).expect("--triangles N"),
            "--frames" => frames = args.next().and_then(|s| s.parse().ok()).expect("--frames N"),
            "--png" => png = args.next(),
            // As while the camera moves.
            "--moving" => antialias = false,
            "--size" => {
                let s = args.next().expect("--size WxH");
                let (w, h) = s.split_once('x').expect("--size WxH");
                size = [w.parse().expect("width"), h.parse().expect("height")];
            }
            // cargo bench passes --bench.
            _ => {}
        }
    }
    let state = create_render_state(default_wgpu_setup(), Default::default());
    let info = state.adapter.get_info();
    let mesh = Arc::new(torus(triangles));
    println!("adapter: {} ({:?}, {:?})", info.name, info.device_type, info.backend);
    println!(
        "mesh: {} triangles, {} vertices; view {}x{} px",
        mesh.triangle_count(),
        mesh.positions.len(),
        size[0],
        size[1]
    );
    let mut renderer = Renderer3d::new(&state.device, state.target_format);
    let mut orbit = Orbit::default();
    let mut times = Vec::new();
    for k in 0..=frames {
        // Turning a little each frame, as an orbit drag does.
        orbit.turn(Vec2::new(3.0, 0.0));
        let camera = orbit.camera(&mesh.bounds, size[0] as f32 / size[1] as f32);
        let frame = Frame3d {
            view_id: 1,
            size_px: size,
            clip_from_world: camera.clip_from_world,
            eye_mm: camera.eye_mm,
            light: camera.light_dir(),
            background: [0.04, 0.04, 0.04, 1.0],
            draws: vec![Draw { mesh: mesh.clone(), rgba: [0.86, 0.72, 0.45, 1.0] }],
            antialias,
        };
        let start = Instant::now();
        let mut encoder = state.device.create_command_encoder(&Default::default());
        renderer.render(&state.device, &state.queue, &mut encoder, &frame);
        state.queue.submit([encoder.finish()]);
        state.device.poll(wgpu::PollType::Wait { submission_index: None, timeout: None }).expect("the frame finishes");
        let took = start.elapsed();
        if k == 0 {
            println!("first frame (pipelines, targets and upload): {:.1} ms", took.as_secs_f64() * 1e3);
        } else {
            times.push(took);
        }
    }
    times.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!(
        "frame: p50 {:.1} ms, p95 {:.1} ms, worst {:.1} ms over {} frames",
        ms(percentile(&times, 0.5)),
        ms(percentile(&times, 0.95)),
        ms(*times.last().unwrap()),
        times.len()
    );
    if let Some(path) = png {
        let texture = renderer.picture(1).expect("the view was drawn");
        let row = (size[0] * 4).div_ceil(256) * 256;
        let buffer = state.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: u64::from(row * size[1]),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = state.device.create_command_encoder(&Default::default());
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
            },
            texture.size(),
        );
        state.queue.submit([encoder.finish()]);
        buffer.slice(..).map_async(wgpu::MapMode::Read, |r| r.expect("the picture maps"));
        state.device.poll(wgpu::PollType::Wait { submission_index: None, timeout: None }).expect("the copy finishes");
        let data = buffer.slice(..).get_mapped_range().expect("the mapped picture");
        let mut pixels = Vec::with_capacity((size[0] * size[1] * 4) as usize);
        for y in 0..size[1] {
            let start = (y * row) as usize;
            pixels.extend_from_slice(&data[start..start + (size[0] * 4) as usize]);
        }
        image::RgbaImage::from_raw(size[0], size[1], pixels)
            .expect("the picture's size")
            .save(&path)
            .expect("the PNG writes");
        println!("wrote {path}");
    }
}
