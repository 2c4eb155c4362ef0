//! The shell a quilt lies in over a curved base (the paper's section 3.2):
//! each base triangle and its offset `height_mm` above make a prism, and a
//! point at barycentric coordinates `b` and height `h` of a face maps to
//! `Σ b_k (p_k + h d_k)`, with one offset direction `d_k` per base vertex.
//!
//! Offsetting along the normals, the simple choice, stretches the shell
//! over convex parts and folds it inside concave ones, where a texture
//! would cross itself. The directions are instead tuned to minimize the
//! shell's L² stretch (Sander et al.'s measure, taken over the three
//! tetrahedra of each prism), by random line searches that move each
//! offset vertex within its tangent plane, as the paper does for its
//! shell map's offset vertices. A folded (inverted) tetrahedron costs far
//! more than any stretch, so folds are undone first.

use glam::{DMat3, DVec3};

use crate::random::SplitMix64;
use crate::surface::SurfaceMesh;

/// Sweeps of line searches over every offset vertex.
const SWEEPS: usize = 6;

/// Most rounds of smoothing spent undoing folds.
const UNFOLD_ROUNDS: usize = 200;

/// Cost of one inverted tetrahedron, in units of a tetrahedron's share of
/// the whole shell's stretch: far above anything stretch alone costs.
const INVERTED_COST: f64 = 1.0e6;

/// The three tetrahedra a prism is cut into: corners 0–2 at the base,
/// 3–5 above them.
const TETRAHEDRA: [[usize; 4]; 3] = [[0, 1, 2, 5], [0, 1, 5, 4], [0, 4, 5, 3]];

/// The shell over a base: one offset per base vertex.
pub struct Shell {
    /// The shell's thickness, mm.
    pub height_mm: f64,
    /// Each base vertex's offset direction (its length is 1 along the normal).
    directions: Vec<DVec3>,
}

/// How much the shell stretches what it carries.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShellStretch {
    /// Volume-weighted root-mean-square stretch over the shell's
    /// tetrahedra that are not inverted (1 for a flat base).
    pub l2: f64,
    /// Tetrahedra turned inside out: where the shell folds.
    pub inverted: usize,
}

impl Shell {
    /// The shell offset along the base's smooth normals.
    pub fn along_normals(surface: &SurfaceMesh, height_mm: f64) -> Shell {
        let directions = (0..surface.positions().len() as u32).map(|v| surface.vertex_normal(v)).collect();
        Shell { height_mm, directions }
    }

    /// The shell with its offsets tuned to the least stretch (see the
    /// module's notes); `seed` drives the random search directions.
    pub fn least_stretch(surface: &SurfaceMesh, height_mm: f64, seed: u64) -> Shell {
        let mut shell = Shell::along_normals(surface, height_mm);
        shell.unfold(surface);
        shell.relax(surface, seed);
        shell
    }

    /// The point at `barycentric` in base `face`, `height_mm` up the shell.
    pub fn point(&self, surface: &SurfaceMesh, face: u32, barycentric: [f64; 3], height_mm: f64) -> DVec3 {
        let t = surface.triangles()[face as usize];
        (0..3)
            .map(|k| (surface.positions()[t[k] as usize] + self.directions[t[k] as usize] * height_mm) * barycentric[k])
            .sum()
    }

    /// The shell's stretch, over every prism.
    pub fn stretch(&self, surface: &SurfaceMesh) -> ShellStretch {
        let (mut weighted, mut volume, mut inverted) = (0.0, 0.0, 0);
        for f in 0..surface.triangles().len() {
            for tet in self.prism_tetrahedra(surface, f) {
                match tet {
                    Some((sigma, v)) => {
                        weighted += sigma * sigma * v;
                        volume += v;
                    }
                    None => inverted += 1,
                }
            }
        }
        ShellStretch { l2: if volume > 0.0 { (weighted / volume).sqrt() } else { 1.0 }, inverted }
    }

    /// Each tetrahedron of face `f`'s prism: its stretch and shell volume,
    /// or `None` where it is inverted.
    fn prism_tetrahedra(&self, surface: &SurfaceMesh, f: usize) -> [Option<(f64, f64)>; 3] {
        let t = surface.triangles()[f];
        let base = t.map(|v| surface.positions()[v as usize]);
        let h = self.height_mm;
        let shell: [DVec3; 6] =
            std::array::from_fn(|k| if k < 3 { base[k] } else { base[k - 3] + self.directions[t[k - 3] as usize] * h });
        // The texture's prism: the triangle laid flat, `h` tall.
        let x = (base[1] - base[0]).normalize_or_zero();
        let n = (base[1] - base[0]).cross(base[2] - base[0]).normalize_or_zero();
        let y = n.cross(x);
        let flat: [DVec3; 3] = base.map(|p| DVec3::new((p - base[0]).dot(x), (p - base[0]).dot(y), 0.0));
        let texture: [DVec3; 6] = std::array::from_fn(|k| if k < 3 { flat[k] } else { flat[k - 3] + DVec3::Z * h });
        TETRAHEDRA.map(|[a, b, c, d]| {
            let edges = |p: &[DVec3; 6]| DMat3::from_cols(p[b] - p[a], p[c] - p[a], p[d] - p[a]);
            let (s, q) = (edges(&shell), edges(&texture));
            let (ds, dq) = (s.determinant(), q.determinant());
            if ds <= 0.0 || dq <= 0.0 {
                return None;
            }
            // g maps the shell to the texture: its Jacobian is q s⁻¹.
            let g = q * s.inverse();
            let sigma =
                ((g.x_axis.length_squared() + g.y_axis.length_squared() + g.z_axis.length_squared()) / 3.0).sqrt();
            Some((sigma, ds / 6.0))
        })
    }

    /// The cost the search lowers over the prisms of `faces`.
    fn cost(&self, surface: &SurfaceMesh, faces: &[u32]) -> f64 {
        faces
            .iter()
            .flat_map(|&f| self.prism_tetrahedra(surface, f as usize))
            .map(|tet| match tet {
                Some((sigma, v)) => sigma * sigma * v,
                None => INVERTED_COST * self.height_mm.powi(3),
            })
            .sum()
    }

    /// Smooths the offset surface where the shell folds (each offset
    /// vertex towards the mean of its neighbours', at the same height)
    /// until no prism is inverted, or a limit of rounds: a fold a line
    /// search cannot climb out of, since undoing it moves many vertices.
    fn unfold(&mut self, surface: &SurfaceMesh) {
        let n = self.directions.len();
        let ring = crate::mesh::vertex_rings(n, surface.triangles());
        let h = self.height_mm;
        let p = surface.positions();
        for _ in 0..UNFOLD_ROUNDS {
            let mut active = vec![false; n];
            for (f, t) in surface.triangles().iter().enumerate() {
                if self.prism_tetrahedra(surface, f).iter().any(Option::is_none) {
                    for &v in t {
                        active[v as usize] = true;
                    }
                }
            }
            if !active.contains(&true) {
                return;
            }
            // Two rings around the fold move with it.
            for _ in 0..2 {
                let grown: Vec<usize> =
                    (0..n).filter(|&v| active[v]).flat_map(|v| ring[v].iter().map(|&w| w as usize)).collect();
                for v in grown {
                    active[v] = true;
                }
            }
            let next: Vec<DVec3> = (0..n)
                .map(|v| {
                    if !active[v] || ring[v].is_empty() {
                        return self.directions[v];
                    }
                    let mean = ring[v].iter().map(|&w| p[w as usize] + self.directions[w as usize] * h).sum::<DVec3>()
                        / ring[v].len() as f64;
                    let normal = surface.vertex_normal(v as u32);
                    let d = (mean - p[v]) / h;
                    d + normal * (1.0 - d.dot(normal))
                })
                .collect();
            self.directions = next;
        }
    }

    fn relax(&mut self, surface: &SurfaceMesh, seed: u64) {
        let n = self.directions.len();
        let mut faces_of: Vec<Vec<u32>> = vec![Vec::new(); n];
        let mut edge_sum = vec![0.0; n];
        let mut edge_count = vec![0usize; n];
        for (f, t) in surface.triangles().iter().enumerate() {
            for k in 0..3 {
                faces_of[t[k] as usize].push(f as u32);
                let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
                let length = surface.positions()[a].distance(surface.positions()[b]);
                edge_sum[a] += length;
                edge_count[a] += 1;
            }
        }
        let mut random = SplitMix64::new(seed);
        let h = self.height_mm;
        for sweep in 0..SWEEPS {
            for v in 0..n {
                if faces_of[v].is_empty() {
                    continue;
                }
                let normal = surface.vertex_normal(v as u32);
                let angle = random.next_unit() * std::f64::consts::TAU;
                let e1 = normal.any_orthonormal_vector();
                let e2 = normal.cross(e1);
                let direction = e1 * angle.cos() + e2 * angle.sin();
                // Steps shrink with the sweeps: coarse moves first.
                let reach = 0.5 * edge_sum[v] / edge_count[v].max(1) as f64 / h / (1 << sweep.min(3)) as f64;
                let start = self.directions[v];
                let mut best = (self.cost(surface, &faces_of[v]), start);
                for step in [reach, -reach, 0.5 * reach, -0.5 * reach, 0.25 * reach, -0.25 * reach] {
                    // The offset vertex moves in its tangent plane: its
                    // height along the normal stays the shell's.
                    let moved = start + direction * step;
                    self.directions[v] = moved;
                    let cost = self.cost(surface, &faces_of[v]);
                    if cost < best.0 {
                        best = (cost, moved);
                    }
                }
                self.directions[v] = best.1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Mesh;
    use crate::surface::builtin_base;

    /// A strip folded into a V, open side up: a concave crease.
    fn valley(depth_mm: f64) -> SurfaceMesh {
        let mut mesh = Mesh::default();
        let (nx, ny) = (21, 6);
        for j in 0..ny {
            for i in 0..nx {
                let x = i as f64 - 10.0;
                mesh.vertices.push([x, j as f64, depth_mm * x.abs() / 10.0]);
            }
        }
        for j in 0..ny - 1 {
            for i in 0..nx - 1 {
                let v = (j * nx + i) as u32;
                let (a, b, c, d) = (v, v + 1, v + nx as u32, v + nx as u32 + 1);
                mesh.triangles.push([a, b, d]);
                mesh.triangles.push([a, d, c]);
            }
        }
        SurfaceMesh::new(mesh).unwrap()
    }

    #[test]
    fn a_flat_base_has_no_stretch() {
        let shell = Shell::along_normals(&valley(0.0), 2.0);
        let stretch = shell.stretch(&valley(0.0));
        assert_eq!(stretch.inverted, 0);
        assert!((stretch.l2 - 1.0).abs() < 1e-9, "{stretch:?}");
    }

    #[test]
    fn a_fold_in_a_concave_crease_is_undone_and_stretch_falls() {
        let base = valley(10.0);
        let before = Shell::along_normals(&base, 3.0).stretch(&base);
        assert!(before.inverted > 0, "the normals should fold the shell: {before:?}");
        let shell = Shell::least_stretch(&base, 3.0, 1);
        let after = shell.stretch(&base);
        assert_eq!(after.inverted, 0, "before {before:?}, after {after:?}");
        assert!(after.l2 < 1.5, "{after:?}");
    }

    #[test]
    fn stretch_on_a_vase_does_not_grow() {
        let base = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap();
        let before = Shell::along_normals(&base, 3.0).stretch(&base);
        let after = Shell::least_stretch(&base, 3.0, 1).stretch(&base);
        assert_eq!(after.inverted, 0);
        assert!(after.l2 <= before.l2 + 1e-9, "before {before:?}, after {after:?}");
    }
}
