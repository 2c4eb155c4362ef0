//! How rounding corners changes hand-drawn strokes.
use tracery_core::curve::{Curve, DrawnStroke};

fn hausdorff(a: &Curve, b: &Curve) -> (f64, f64) {
    let ab = a.points().iter().map(|&p| b.distance(p)).fold(0.0, f64::max);
    let ba = b.points().iter().map(|&p| a.distance(p)).fold(0.0, f64::max);
    (ab, ba)
}

fn main() {
    let r = 6.25;
    for seed in 0..3 {
        for s in DrawnStroke::set(seed) {
            for s in [s.clone(), s.reversed()] {
                let drawn = s.curve().unwrap();
                let t = std::time::Instant::now();
                let followed = drawn.with_rounded_corners(r);
                let ms = t.elapsed().as_secs_f64() * 1e3;
                let (fd, df) = hausdorff(&followed, &drawn);
                println!(
                    "{:24} n={:3} drawn {:7.1} followed {:7.1} ratio {:5.2} off {:5.2} {:5.2} {ms:.1}ms",
                    s.name(),
                    s.samples_mm.len(),
                    drawn.length(),
                    followed.length(),
                    followed.length() / drawn.length(),
                    fd,
                    df
                );
            }
        }
    }
}
