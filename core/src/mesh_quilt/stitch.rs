//! Stitching: two cut elements joined into one closed surface by a strip
//! of triangles between each pair of facing boundary loops.

use glam::DVec3;

use super::Element;

/// Joins `a` and `b`, whose boundary loops face each other in pairs, into
/// one element. Returns `None` unless every loop finds its partner and the
/// result is a closed surface.
pub fn stitch(a: &Element, b: &Element, reach_mm: f64) -> Option<Element> {
    let loops_a = a.boundary_loops();
    let mut loops_b = b.boundary_loops();
    if loops_a.is_empty() || loops_a.len() != loops_b.len() {
        return None;
    }
    let centre = |e: &Element, l: &[u32]| l.iter().map(|&v| e.vertices[v as usize]).sum::<DVec3>() / l.len() as f64;
    let mut joined = a.clone();
    let offset = joined.vertices.len() as u32;
    joined.append(b);
    for la in &loops_a {
        let ca = centre(a, la);
        let (k, distance) = loops_b
            .iter()
            .enumerate()
            .map(|(k, lb)| (k, centre(b, lb).distance(ca)))
            .min_by(|x, y| x.1.total_cmp(&y.1))?;
        if distance > reach_mm {
            return None;
        }
        let lb: Vec<u32> = loops_b.swap_remove(k).iter().map(|&v| v + offset).collect();
        zip(&mut joined, la, &lb);
    }
    joined.is_closed().then_some(joined)
}

/// Triangles between loop `a` (walked forward) and loop `b` (walked
/// backward), from the pair of corners nearest each other, chosen so that
/// the edges across the strip are as short as they can be in sum (a
/// shortest path through the grid of corner pairs). Both loops run as
/// their own triangles do, so on facing cuts they run opposite ways, and
/// the strip's edges along them run back, closing the surface. Choosing
/// each step greedily by the shorter next edge could wander, where two
/// pieces stand a gap apart, and come back round to a corner it had left,
/// joining the same two corners twice.
fn zip(mesh: &mut Element, a: &[u32], b: &[u32]) {
    let p = |v: u32| mesh.vertices[v as usize];
    let (n, m) = (a.len(), b.len());
    let start_b = (0..m).min_by(|&x, &y| p(b[x]).distance(p(a[0])).total_cmp(&p(b[y]).distance(p(a[0])))).unwrap_or(0);
    let at_a = |i: usize| a[i % n];
    let at_b = |j: usize| b[(start_b + m * 2 - j % m) % m];
    let across = |i: usize, j: usize| p(at_a(i)).distance(p(at_b(j)));
    // cost[i][j]: the least sum of edges across, from (0, 0) to (i, j);
    // from[i][j]: whether that path's last step advanced along `a`.
    let width = m + 1;
    let mut cost = vec![f64::INFINITY; (n + 1) * width];
    let mut from_a = vec![false; (n + 1) * width];
    cost[0] = 0.0;
    for i in 0..=n {
        for j in 0..=m {
            let here = across(i, j);
            if i > 0 && cost[(i - 1) * width + j] + here < cost[i * width + j] {
                cost[i * width + j] = cost[(i - 1) * width + j] + here;
                from_a[i * width + j] = true;
            }
            if j > 0 && cost[i * width + j - 1] + here < cost[i * width + j] {
                cost[i * width + j] = cost[i * width + j - 1] + here;
                from_a[i * width + j] = false;
            }
        }
    }
    let (mut i, mut j) = (n, m);
    let mut strip = Vec::with_capacity(n + m);
    while i > 0 || j > 0 {
        if from_a[i * width + j] {
            strip.push([at_a(i), at_a(i - 1), at_b(j)]);
            i -= 1;
        } else {
            strip.push([at_b(j - 1), at_b(j), at_a(i)]);
            j -= 1;
        }
    }
    mesh.triangles.extend(strip);
}
