//! Renders binary STL files to PNG pictures for looking at them: a z-buffer
//! with Lambert shading, seen from the side and a little above.
//!
//! `cargo run -p tracery-core --release --example mesh_png -- IN.stl OUT.png [SIZE_PX] [BASE]`
//!
//! `BASE`, a built-in base's name or another STL, is drawn in grey with it.

use glam::DVec3;

/// The triangles of an STL file, by the project's own reader.
fn read_stl(path: &str) -> Vec<[DVec3; 3]> {
    triangles_of(&tracery_core::mesh::read_stl(&std::fs::read(path).expect("read STL"), path).expect("parse STL"))
}

fn triangles_of(mesh: &tracery_core::mesh::Mesh) -> Vec<[DVec3; 3]> {
    mesh.triangles.iter().map(|t| t.map(|i| DVec3::from_array(mesh.vertices[i as usize]))).collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (input, output) = (&args[1], &args[2]);
    let size: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(900);
    let mut triangles: Vec<([DVec3; 3], bool)> = read_stl(input).into_iter().map(|t| (t, false)).collect();
    if let Some(base) = args.get(4) {
        let extra = match tracery_core::surface::builtin_base(base) {
            Some(mesh) => {
                mesh.triangles.iter().map(|t| t.map(|i| DVec3::from_array(mesh.vertices[i as usize]))).collect()
            }
            None => read_stl(base),
        };
        triangles.extend(extra.into_iter().map(|t| (t, true)));
    }
    // Camera: looking along -y (from the front), tilted 25° down.
    let tilt = std::env::var("MESH_PNG_TILT_DEG").ok().and_then(|s| s.parse::<f64>().ok()).unwrap_or(25.0).to_radians();
    let turn = std::env::var("MESH_PNG_TURN_DEG").ok().and_then(|s| s.parse::<f64>().ok()).unwrap_or(0.0).to_radians();
    let (st, ct) = turn.sin_cos();
    let spin = |v: DVec3| DVec3::new(ct * v.x - st * v.y, st * v.x + ct * v.y, v.z);
    let forward = spin(DVec3::new(0.0, tilt.cos(), -tilt.sin()));
    let up = spin(DVec3::new(0.0, tilt.sin(), tilt.cos()));
    let right = forward.cross(up);
    let project = |p: DVec3| DVec3::new(p.dot(right), p.dot(up), p.dot(forward));
    let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
    for (t, _) in &triangles {
        for &p in t {
            lo = lo.min(project(p));
            hi = hi.max(project(p));
        }
    }
    let scale = 0.94 * size as f64 / (hi.x - lo.x).max(hi.y - lo.y);
    let offset = 0.5 * (DVec3::splat(size as f64) - (hi - lo) * scale);
    let to_px = |p: DVec3| {
        let q = project(p);
        DVec3::new((q.x - lo.x) * scale + offset.x, size as f64 - ((q.y - lo.y) * scale + offset.y), q.z)
    };
    let light = DVec3::new(-0.4, -0.8, 0.5).normalize();
    let mut depth = vec![f64::MAX; size * size];
    let mut rgb = vec![255u8; size * size * 3];
    for (t, is_base) in &triangles {
        let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
        let shade = 0.25 + 0.75 * n.dot(-light).abs();
        let facing = n.dot(forward) < 0.0;
        let colour = match (is_base, facing) {
            (true, _) => [175.0, 175.0, 175.0],
            (false, true) => [200.0, 170.0, 120.0],
            (false, false) => [120.0, 110.0, 160.0],
        };
        let [a, b, c] = t.map(to_px);
        let (x0, x1) = (
            a.x.min(b.x).min(c.x).floor().max(0.0) as usize,
            a.x.max(b.x).max(c.x).ceil().min(size as f64 - 1.0) as usize,
        );
        let (y0, y1) = (
            a.y.min(b.y).min(c.y).floor().max(0.0) as usize,
            a.y.max(b.y).max(c.y).ceil().min(size as f64 - 1.0) as usize,
        );
        let area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if area.abs() < 1e-12 {
            continue;
        }
        for y in y0..=y1 {
            for x in x0..=x1 {
                let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                let w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
                let w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
                let w2 = 1.0 - w0 - w1;
                if w0 < 0.0 || w1 < 0.0 || w2 < 0.0 {
                    continue;
                }
                let z = w0 * a.z + w1 * b.z + w2 * c.z;
                let i = y * size + x;
                if z < depth[i] {
                    depth[i] = z;
                    for k in 0..3 {
                        rgb[3 * i + k] = (colour[k] * shade).min(255.0) as u8;
                    }
                }
            }
        }
    }
    image::save_buffer(output, &rgb, size as u32, size as u32, image::ExtendedColorType::Rgb8).expect("write PNG");
}
