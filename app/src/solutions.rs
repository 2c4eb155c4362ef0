//! A curve's alternative solutions as the gallery shows them, worked out
//! once, off the UI thread, when they arrive.
//!
//! Two alternatives are told apart by [`distinctness`]: the share of the
//! pattern's length where they show different shapes (a loop's rotated copy
//! counts as the same). Alternatives less than [`SAME_BELOW`] apart from one
//! shown before them are not shown again.

use tracery_core::Product;
use tracery_core::product::Fact;
use tracery_core::quality::distinctness;

/// Alternatives differing over less than this share of their length are the same pattern.
pub const SAME_BELOW: f64 = 0.05;

/// A product's pieces as (shape class, 1): pieces count alike.
fn shapes(product: &Product) -> Vec<(usize, f64)> {
    match product.facts.get("shape_sequence") {
        Some(Fact::Indices(v)) => v.iter().map(|&c| (c, 1.0)).collect(),
        _ => Vec::new(),
    }
}

/// A curve's alternatives, the best first, with which to show and how far
/// each is from the best. Comparing loops at every rotation is too costly to
/// repeat every frame, so it is done here, once.
#[derive(Debug)]
pub struct Solutions {
    /// Every alternative, the best first.
    pub products: Vec<Product>,
    /// The ones to show: each differs from all shown before it.
    pub shown: Vec<usize>,
    /// How far each alternative is from the best (0 to 1).
    pub apart_from_best: Vec<f64>,
}

impl Solutions {
    /// Sorts out `products` (alternatives of one curve, closed or not).
    pub fn new(products: Vec<Product>, closed: bool) -> Solutions {
        let sequences: Vec<Vec<(usize, f64)>> = products.iter().map(shapes).collect();
        let apart = |i: usize, j: usize| distinctness(&sequences[i], &sequences[j], closed);
        let mut shown: Vec<usize> = Vec::new();
        for k in 0..products.len() {
            if shown.iter().all(|&j| apart(j, k) >= SAME_BELOW) {
                shown.push(k);
            }
        }
        let apart_from_best = (0..products.len()).map(|k| if k == 0 { 0.0 } else { apart(0, k) }).collect();
        Solutions { products, shown, apart_from_best }
    }
}
