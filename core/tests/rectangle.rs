//! Rectangles (`rect:WxH`, the paper's two passes): the rows differ. The
//! measure is the pattern's own picture, sampled on a grid, against itself
//! shifted up: a rectangle whose rows are all the same strip agrees with
//! itself shifted by one row almost everywhere.

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::Region;
use tracery_core::vector_brush::{Settings, builtin, make_product};

/// Sampling step, mm.
const STEP_MM: f64 = 0.25;

/// The largest share of grid points whose inside-or-out agrees with the
/// point `shift` above, over vertical shifts from `min_shift_mm` to half the height.
fn best_self_agreement(region: &Region, min_shift_mm: f64) -> (f64, f64) {
    let bounds = region.bounds().unwrap();
    let (nx, ny) = ((bounds.width() / STEP_MM) as usize, (bounds.height() / STEP_MM) as usize);
    let inside: Vec<Vec<bool>> = (0..ny)
        .map(|j| {
            (0..nx)
                .map(|i| region.contains(bounds.min + DVec2::new(i as f64 + 0.5, j as f64 + 0.5) * STEP_MM))
                .collect()
        })
        .collect();
    let mut best = (0.0, 0.0);
    for shift in (min_shift_mm / STEP_MM) as usize..ny / 2 {
        let (mut same, mut all) = (0usize, 0usize);
        for (low, high) in inside.iter().zip(&inside[shift..]) {
            same += low.iter().zip(high).filter(|(a, b)| a == b).count();
            all += nx;
        }
        let agreement = same as f64 / all as f64;
        if agreement > best.0 {
            best = (agreement, shift as f64 * STEP_MM);
        }
    }
    best
}

#[test]
fn the_rows_of_a_rectangle_differ() {
    for name in ["islands", "lace"] {
        let exemplar = builtin(name).unwrap();
        let settings = Settings::default();
        let along = Along::parse("rect:80x60").unwrap();
        let product = make_product(&exemplar, &along, &settings, &Control::default()).unwrap();
        assert_eq!(product.topology.components, 1, "{name}");
        // Shifts of at least half a row: smaller ones compare a row with itself.
        let (agreement, shift) = best_self_agreement(&product.region_mm, 0.5 * settings.band_mm);
        eprintln!("{name}: best agreement {agreement:.3} at a shift of {shift} mm");
        assert!(agreement < 0.9, "{name}: the rectangle agrees with itself {agreement:.3} shifted by {shift} mm");
    }
}
