//! Specks and pinholes of a picture: opaque parts and enclosed transparent
//! holes of very few pixels, which are noise of the picture (a stray
//! anti-aliased pixel), not parts or holes anyone drew or could print.

/// Parts and holes of fewer pixels than this are specks and pinholes.
pub const MIN_PART_PX: usize = 2;

/// Erases opaque parts (4-connected pixels at or above `threshold`) and
/// fills enclosed holes (4-connected pixels below it that do not reach the
/// grid's edge) of fewer than [`MIN_PART_PX`] pixels. `values` is a `w` ×
/// `h` grid, row by row. Run it after joining corners, so that two opaque
/// pixels meeting at a corner already share an edge and are one part.
///
/// ```
/// use tracery_core::geom::remove_specks;
/// // A 3 x 3 opaque block with a pinhole, and a lone pixel apart from it.
/// let mut v = vec![0.0; 7 * 5];
/// for y in 1..4 {
///     for x in 1..4 {
///         v[y * 7 + x] = 1.0;
///     }
/// }
/// v[2 * 7 + 2] = 0.0;
/// v[2 * 7 + 5] = 1.0;
/// remove_specks(&mut v, 7, 5, 0.5);
/// assert_eq!(v[2 * 7 + 2], 1.0, "the pinhole is filled");
/// assert_eq!(v[2 * 7 + 5], 0.0, "the speck is erased");
/// ```
pub fn remove_specks(values: &mut [f64], w: usize, h: usize, threshold: f64) {
    if values.len() != w * h {
        return;
    }
    for opaque in [true, false] {
        let mut seen = vec![false; w * h];
        let mut part = Vec::new();
        for start in 0..w * h {
            if seen[start] || (values[start] >= threshold) != opaque {
                continue;
            }
            part.clear();
            let mut reaches_edge = false;
            seen[start] = true;
            let mut stack = vec![start];
            while let Some(i) = stack.pop() {
                part.push(i);
                let (x, y) = (i % w, i / w);
                reaches_edge |= x == 0 || y == 0 || x + 1 == w || y + 1 == h;
                let neighbours = [
                    (x > 0).then(|| i - 1),
                    (x + 1 < w).then(|| i + 1),
                    (y > 0).then(|| i - w),
                    (y + 1 < h).then(|| i + w),
                ];
                for j in neighbours.into_iter().flatten() {
                    if !seen[j] && (values[j] >= threshold) == opaque {
                        seen[j] = true;
                        stack.push(j);
                    }
                }
            }
            if part.len() < MIN_PART_PX && (opaque || !reaches_edge) {
                let fill = if opaque { 0.0 } else { 1.0 };
                for &i in &part {
                    values[i] = fill;
                }
            }
        }
    }
}
