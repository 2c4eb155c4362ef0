use tracery_core::report::Timings;
use tracery_core::surface::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let base = SurfaceMesh::new(builtin_base(&args[1]).unwrap()).unwrap();
    let mut s = SurfaceSettings::default();
    s.points_mm = SurfaceSettings::parse_points(&args[2]).unwrap();
    s.closed = args.get(3).is_some_and(|a| a == "closed");
    let mut t = Timings::default();
    let d = draw_on(&base, &s, 8.0, &mut t).unwrap();
    let f = &d.frames;
    let n = f.arc_mm.len();
    let mut worst = (0.0, 0);
    for k in 0..n {
        let j = (k + 1) % n;
        let dd = (f.arc_mm[j] - f.arc_mm[k]).abs();
        if dd > 1e-3 && j != 0 {
            let a = f.binormals[k].angle_between(f.binormals[j]).to_degrees() / dd;
            if a > worst.0 {
                worst = (a, k);
            }
        }
    }
    println!("n={n} len={} worst={:?} turn={}", f.length_mm, worst, f.max_turn_deg_per_mm());
    let k = worst.1;
    for i in k.saturating_sub(3)..(k + 4).min(n) {
        println!(
            "{i} arc={:.4} p={:?} t={:?} b={:?} nrm={:?}",
            f.arc_mm[i], d.curve.points_mm[i], f.tangents[i], f.binormals[i], d.curve.normals[i]
        );
    }
    let zs: Vec<f64> = d.curve.points_mm.iter().map(|p| p.z).collect();
    println!(
        "z {:?} .. {:?}",
        zs.iter().cloned().fold(f64::MAX, f64::min),
        zs.iter().cloned().fold(f64::MIN, f64::max)
    );
    for k in (0..n).step_by(n / 20) {
        println!("{:?}", d.curve.points_mm[k]);
    }
    let band = BandOnSurface { surface: &base, curve: &d.curve, frames: &d.frames, conform: true };
    let mid = 0.5 * d.frames.length_mm;
    let mut last = None;
    let _ = mid;
    for vv in [-4.0, -2.0, 0.0, 2.0, 4.0] {
        last = None;
        for i in 0..=8000 {
            let u = d.frames.length_mm * i as f64 / 8000.0;
            let p = band.surface_from_band(glam::DVec2::new(u, vv), 0.0);
            if let Some(q) = last {
                let jump: f64 = glam::DVec3::distance(p, q);
                if jump > 0.03 {
                    println!("jump at u={u:.3}: {jump:.3} {:?} {:?}", q, p);
                }
            }
            last = Some(p);
        }
    }
    println!("{:?}", t);
}
// (appended) z range printer
