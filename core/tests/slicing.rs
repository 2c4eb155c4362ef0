//! Cutting exemplars into pieces: uniform and topology-driven slicing, thin features.

use tracery_core::vector_brush::{
    BUILTIN_NAMES, PieceSet, SliceError, SliceOptions, SlicingMode, builtin, cut_positions, portals_at, topology_events,
};

#[test]
fn uniform_slicing_cuts_evenly() {
    let exemplar = builtin("lace").unwrap();
    let mut options = SliceOptions::default();
    options.mode = SlicingMode::Uniform { cuts: 7 };
    let set = PieceSet::new(&exemplar, &options).unwrap();
    assert_eq!(set.len(), 8);
    for piece in &set.pieces {
        assert!((piece.width - exemplar.width() / 8.0).abs() < 1e-3 * exemplar.width());
    }
    let total: f64 = set.pieces.iter().map(|p| p.region.area()).sum();
    assert!((total - exemplar.region.area()).abs() < 1e-6 * exemplar.region.area());
}

#[test]
fn topology_slicing_puts_one_event_group_in_each_piece() {
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).unwrap();
        let options = SliceOptions::default();
        let set = PieceSet::new(&exemplar, &options).unwrap();
        assert!(set.len() >= 10, "{name}: {} pieces", set.len());
        let events = topology_events(&exemplar.region);
        let grouping = options.event_grouping * exemplar.height();
        for piece in &set.pieces {
            let inside: Vec<f64> =
                events.iter().copied().filter(|&e| e >= piece.u_start && e <= piece.u_end()).collect();
            assert!(!inside.is_empty(), "{name}: piece {} holds no topology event", piece.index);
            // All events inside one piece belong to one group.
            let span = inside.last().unwrap() - inside.first().unwrap();
            assert!(span <= grouping + 1e-9, "{name}: piece {} spans events over {span}", piece.index);
        }
        // Portals at both sides of every cut agree between neighbours.
        for pair in set.pieces.windows(2) {
            assert_eq!(pair[0].right, pair[1].left, "{name}");
        }
        assert!(set.pieces.first().unwrap().left.is_empty() && set.pieces.last().unwrap().right.is_empty());
    }
}

#[test]
fn thin_feature_filter_drops_weak_cuts() {
    let exemplar = builtin("filigree").unwrap();
    let all = cut_positions(&exemplar, &SliceOptions::default()).unwrap();
    let narrowest = |c: f64| portals_at(&exemplar.region, c).iter().map(|p| p.width()).fold(f64::INFINITY, f64::min);
    // The hairline bridges are 0.8 units thick.
    assert!(all.iter().any(|&c| narrowest(c) < 1.0));
    let mut options = SliceOptions::default();
    options.min_portal = 1.0;
    let strong = cut_positions(&exemplar, &options).unwrap();
    assert!(strong.len() < all.len());
    assert!(strong.iter().all(|&c| narrowest(c) >= 1.0));
    // Pieces still tile the exemplar.
    let set = PieceSet::new(&exemplar, &options).unwrap();
    let total: f64 = set.pieces.iter().map(|p| p.region.area()).sum();
    assert!((total - exemplar.region.area()).abs() < 1e-6 * exemplar.region.area());
}

#[test]
fn bad_slicing_options_are_errors() {
    let exemplar = builtin("lace").unwrap();
    let mut options = SliceOptions::default();
    options.mode = SlicingMode::Uniform { cuts: 500 };
    assert!(matches!(PieceSet::new(&exemplar, &options), Err(SliceError::TooManyPieces { .. })));
    options.mode = SlicingMode::Topology;
    options.min_portal = -1.0;
    assert!(matches!(PieceSet::new(&exemplar, &options), Err(SliceError::InvalidOption(_))));
}

#[test]
fn a_piece_with_hundreds_of_parts_keeps_them_apart() {
    // 600 specks beside a bar that runs through every cut: polygon indices
    // go far past 255, and an index that wrapped onto the bar's would count
    // a speck as touching a portal.
    let mut body = String::from(r#"<rect x="0" y="40" width="100" height="20"/>"#);
    for i in 0..30 {
        for j in 0..20 {
            body.push_str(&format!(r#"<rect x="{}" y="{}" width="0.5" height="0.5"/>"#, 1 + i, j));
        }
    }
    let svg = format!(r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 60">{body}</svg>"#);
    let exemplar = tracery_core::vector_brush::Exemplar::from_svg_str(
        "specks",
        &svg,
        &tracery_core::vector_brush::LoadOptions::default(),
    )
    .unwrap();
    let mut options = SliceOptions::default();
    options.mode = SlicingMode::Uniform { cuts: 2 };
    let set = PieceSet::new(&exemplar, &options).unwrap();
    let first = &set.pieces[0];
    // Counted on the piece's geometry: the bar plus every speck.
    let parts = tracery_core::geom::count_topology(&first.region).components as u32;
    assert_eq!(parts, 601);
    assert_eq!(first.descriptor.right().len(), 1);
    assert_eq!(first.descriptor.closed_components(), parts - 1);
    assert_eq!(first.descriptor.components(), parts);
}

/// Clipping a strip out of a drawing overlays only the rings that reach the
/// strip; the pieces must come out exactly, to the last bit, as intersecting
/// the whole drawing with the strip gives them.
#[test]
fn clipping_a_strip_gives_exactly_what_intersecting_the_whole_drawing_does() {
    use tracery_core::DVec2;
    use tracery_core::geom::{Polygon, Rect, Region, clip_to_rect, intersection};
    let mut strips = 0;
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).unwrap();
        let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
        let (width, b) = (exemplar.width(), exemplar.bounds);
        let margin = exemplar.height().max(width);
        // The pieces' own strips, and strips of other widths cutting the
        // drawing anywhere (through rings, between them, past its ends).
        let mut spans: Vec<(f64, f64)> = set.pieces.iter().map(|p| (p.u_start, p.u_start + p.width)).collect();
        spans.extend((0..12).map(|k| (width * (k as f64 * 0.093 - 0.05), width * (k as f64 * 0.093 + 0.11))));
        for (a, c) in spans {
            let rect = Rect::new(DVec2::new(a, b.min.y - margin), DVec2::new(c, b.max.y + margin));
            let strip = Region::new(vec![Polygon { outer: rect.corners().to_vec(), holes: vec![] }]);
            assert_eq!(
                clip_to_rect(&exemplar.region, &rect),
                intersection(&exemplar.region, &strip),
                "{name} [{a}, {c}]"
            );
            strips += 1;
        }
    }
    assert!(strips > 100);
}
