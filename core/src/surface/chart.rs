//! A chart: the part of a base mesh around the points a person picked, cut
//! to a disk and laid flat onto the unit disk by Floater's mean-value
//! parameterization (a sparse solve through faer).
//!
//! Which part: every triangle whose corners lie within a margin (graph
//! distance along edges) of the shortest edge paths joining the picked
//! points. A chart that is an annulus (a ring around a vase) or has holes
//! gets every boundary loop but the longest closed by a fan around a new
//! vertex; the curve may go around such a fan but not through it. A chart
//! that still is not a disk (a band around a torus's handle both ways)
//! is refused. On a closed mesh the margin is kept short of the farthest
//! vertex, so the chart always has a boundary to pin to the circle.
//!
//! Mean-value weights are positive, so with the boundary on a circle
//! (convex) the map is one-to-one (Floater 2003): no triangle flips.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, HashSet};

use faer::Mat;
use faer::prelude::Solve;
use faer::sparse::{SparseColMat, Triplet};
use glam::{DVec2, DVec3};

use super::{SurfaceMesh, SurfacePoint};
use crate::geom::{TriangleGrid, barycentric};

/// Why no chart could be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ChartError {
    /// Two picked points lie on parts of the mesh that do not touch.
    #[error("points {from} and {to} lie on separate parts of the mesh")]
    Apart {
        /// The first point, from 1.
        from: usize,
        /// The second.
        to: usize,
    },
    /// The part around the points is not a disk even with holes closed.
    #[error(
        "the curve runs around a handle of the mesh (the part around it has Euler characteristic {euler}, a disk has 1); draw a shorter curve or pick points closer together"
    )]
    NotDisk {
        /// Euler characteristic found.
        euler: i64,
    },
    /// The sparse solve failed.
    #[error("the surface could not be laid flat: {0}")]
    Solve(String),
}

/// Fewest picked points a curve needs.
pub const MIN_POINTS: usize = 2;

/// A part of a base mesh laid flat on the unit disk.
pub struct Chart {
    /// Each chart vertex's mesh vertex, or `None` for the centre of a filled hole.
    vertex_of: Vec<Option<u32>>,
    local_of: HashMap<u32, u32>,
    /// Chart vertices on the unit disk.
    uv: Vec<DVec2>,
    /// Chart triangles, counter-clockwise on the disk.
    triangles: Vec<[u32; 3]>,
    /// Each chart triangle's mesh face, or `None` for a fan closing a hole.
    face_of: Vec<Option<u32>>,
    chart_triangle_of: HashMap<u32, u32>,
    grid: TriangleGrid,
}

impl Chart {
    /// The chart around `points` (joined in order, and back to the first
    /// when `closed`), reaching `margin_mm` beyond the paths between them.
    pub fn around(
        surface: &SurfaceMesh,
        points: &[SurfacePoint],
        closed: bool,
        margin_mm: f64,
    ) -> Result<Chart, ChartError> {
        let graph = VertexGraph::new(surface);
        let corner = |p: &SurfacePoint| {
            let t = surface.triangles()[p.face as usize];
            let k = (0..3).max_by(|&a, &b| p.barycentric[a].total_cmp(&p.barycentric[b])).unwrap_or(0);
            t[k]
        };
        let mut sources: Vec<u32> = points.iter().map(corner).collect();
        let pairs = points.len() - 1 + usize::from(closed && points.len() > 2);
        for k in 0..pairs {
            let (a, b) = (corner(&points[k]), corner(&points[(k + 1) % points.len()]));
            let path = graph.path(a, b).ok_or(ChartError::Apart { from: k + 1, to: (k + 1) % points.len() + 1 })?;
            sources.extend(path);
        }
        let distance = graph.distances(&sources);
        let farthest = distance.iter().copied().filter(|d| d.is_finite()).fold(0.0, f64::max);
        let reach = margin_mm.max(3.0 * graph.longest_edge_mm).min(0.75 * farthest);
        let mut inside: HashSet<u32> = (0..surface.triangles().len() as u32)
            .filter(|&f| surface.triangles()[f as usize].iter().all(|&v| distance[v as usize] <= reach))
            .collect();
        inside.extend(points.iter().map(|p| p.face));
        keep_component(surface, &mut inside, points[0].face);
        untie_bowties(surface, &mut inside);
        Chart::flatten(surface, &inside)
    }

    /// Lays the triangles `inside` flat.
    fn flatten(surface: &SurfaceMesh, inside: &HashSet<u32>) -> Result<Chart, ChartError> {
        let mut faces: Vec<u32> = inside.iter().copied().collect();
        faces.sort_unstable();
        let mut vertex_of: Vec<Option<u32>> = Vec::new();
        let mut local_of: HashMap<u32, u32> = HashMap::new();
        let mut positions: Vec<DVec3> = Vec::new();
        let mut triangles = Vec::with_capacity(faces.len());
        for &f in &faces {
            triangles.push(surface.triangles()[f as usize].map(|v| {
                *local_of.entry(v).or_insert_with(|| {
                    vertex_of.push(Some(v));
                    positions.push(surface.positions()[v as usize]);
                    (vertex_of.len() - 1) as u32
                })
            }));
        }
        let mut face_of: Vec<Option<u32>> = faces.iter().map(|&f| Some(f)).collect();
        let mut loops = crate::mesh::boundary_loops(&triangles);
        let length = |l: &Vec<u32>| -> f64 {
            (0..l.len()).map(|k| positions[l[k] as usize].distance(positions[l[(k + 1) % l.len()] as usize])).sum()
        };
        loops.sort_by(|a, b| length(b).total_cmp(&length(a)));
        if loops.is_empty() {
            return Err(ChartError::NotDisk { euler: 2 });
        }
        // Every hole but the outer boundary is closed by a fan.
        for hole in &loops[1..] {
            let centre = hole.iter().map(|&v| positions[v as usize]).sum::<DVec3>() / hole.len() as f64;
            let fan = vertex_of.len() as u32;
            vertex_of.push(None);
            positions.push(centre);
            for k in 0..hole.len() {
                // The boundary runs a→b in its triangle, so the fan runs b→a.
                triangles.push([hole[(k + 1) % hole.len()], hole[k], fan]);
                face_of.push(None);
            }
        }
        let edges: HashSet<(u32, u32)> = triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
            .collect();
        let euler = vertex_of.len() as i64 - edges.len() as i64 + triangles.len() as i64;
        if euler != 1 {
            return Err(ChartError::NotDisk { euler });
        }
        let uv = mean_value_map(&positions, &triangles, &loops[0])?;
        let chart_triangle_of =
            face_of.iter().enumerate().filter_map(|(t, f)| f.map(|f| (f, t as u32))).collect::<HashMap<_, _>>();
        let grid = TriangleGrid::new(&uv, &triangles, DVec2::splat(-1.0), DVec2::splat(1.0));
        Ok(Chart { vertex_of, local_of, uv, triangles, face_of, chart_triangle_of, grid })
    }

    /// Where the centres of the filled holes lie on the disk.
    pub fn hole_centres(&self) -> Vec<DVec2> {
        self.vertex_of.iter().zip(&self.uv).filter(|(v, _)| v.is_none()).map(|(_, &uv)| uv).collect()
    }

    /// Number of chart triangles (filled holes included).
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Where `point` lies on the disk, if its triangle is in the chart.
    pub fn to_disk(&self, point: &SurfacePoint) -> Option<DVec2> {
        let t = *self.chart_triangle_of.get(&point.face)?;
        Some((0..3).map(|k| self.uv[self.triangles[t as usize][k] as usize] * point.barycentric[k]).sum())
    }

    /// The chart triangle holding `p` on the disk, with barycentric coordinates.
    pub fn locate(&self, p: DVec2) -> Option<(u32, [f64; 3])> {
        self.grid.locate(&self.uv, &self.triangles, p)
    }

    /// Barycentric coordinates of `p` in chart triangle `t` (unclamped).
    pub fn barycentric(&self, t: u32, p: DVec2) -> [f64; 3] {
        barycentric(self.triangles[t as usize].map(|v| self.uv[v as usize]), p)
    }

    /// The chart triangle's corners (chart vertices).
    pub fn corners(&self, t: u32) -> [u32; 3] {
        self.triangles[t as usize]
    }

    /// The mesh face of chart triangle `t`, or `None` where it closes a hole.
    pub fn face(&self, t: u32) -> Option<u32> {
        self.face_of[t as usize]
    }

    /// The mesh vertex of chart vertex `v`, or `None` for a hole's centre.
    pub fn mesh_vertex(&self, v: u32) -> Option<u32> {
        self.vertex_of[v as usize]
    }

    /// The chart vertex of mesh vertex `v`, if it is in the chart.
    pub fn chart_vertex(&self, v: u32) -> Option<u32> {
        self.local_of.get(&v).copied()
    }

    /// The chart triangle of mesh face `f`, if it is in the chart.
    pub fn chart_triangle(&self, f: u32) -> Option<u32> {
        self.chart_triangle_of.get(&f).copied()
    }

    /// Signed areas of the chart's triangles on the disk: all positive when
    /// the map is one-to-one.
    pub fn signed_areas(&self) -> Vec<f64> {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|v| self.uv[v as usize]);
                0.5 * (b - a).perp_dot(c - a)
            })
            .collect()
    }
}

/// Keeps the triangles of `inside` joined to `seed` through edges.
fn keep_component(surface: &SurfaceMesh, inside: &mut HashSet<u32>, seed: u32) {
    let mut kept = HashSet::from([seed]);
    let mut stack = vec![seed];
    while let Some(f) = stack.pop() {
        let t = surface.triangles()[f as usize];
        for k in 0..3 {
            for &g in surface.faces_on_edge(t[k], t[(k + 1) % 3]) {
                if inside.contains(&g) && kept.insert(g) {
                    stack.push(g);
                }
            }
        }
    }
    *inside = kept;
}

/// Where the chart's triangles meet at a vertex only by their corners (a
/// bow tie), its boundary has no single next edge: the triangles around
/// such vertices are taken in until there is none.
fn untie_bowties(surface: &SurfaceMesh, inside: &mut HashSet<u32>) {
    for _ in 0..16 {
        let mut outgoing: HashMap<u32, usize> = HashMap::new();
        for &f in inside.iter() {
            let t = surface.triangles()[f as usize];
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                if !surface.faces_on_edge(a, b).iter().any(|g| *g != f && inside.contains(g)) {
                    *outgoing.entry(a).or_default() += 1;
                }
            }
        }
        let tied: HashSet<u32> = outgoing.into_iter().filter(|(_, n)| *n > 1).map(|(v, _)| v).collect();
        if tied.is_empty() {
            return;
        }
        for (f, t) in surface.triangles().iter().enumerate() {
            if t.iter().any(|v| tied.contains(v)) {
                inside.insert(f as u32);
            }
        }
    }
}

/// Floater's mean-value map: `outer` on the unit circle by arc length, every
/// other vertex a positive combination of its neighbours.
fn mean_value_map(positions: &[DVec3], triangles: &[[u32; 3]], outer: &[u32]) -> Result<Vec<DVec2>, ChartError> {
    let n = positions.len();
    let mut uv = vec![DVec2::ZERO; n];
    let mut pinned = vec![false; n];
    let lengths: Vec<f64> = (0..outer.len())
        .map(|k| positions[outer[k] as usize].distance(positions[outer[(k + 1) % outer.len()] as usize]))
        .collect();
    let total: f64 = lengths.iter().sum();
    let mut walked = 0.0;
    for (k, &v) in outer.iter().enumerate() {
        uv[v as usize] = DVec2::from_angle(std::f64::consts::TAU * walked / total);
        pinned[v as usize] = true;
        walked += lengths[k];
    }
    let mut unknown = vec![u32::MAX; n];
    let mut count = 0usize;
    for v in 0..n {
        if !pinned[v] {
            unknown[v] = count as u32;
            count += 1;
        }
    }
    // Weights w_ij += tan(angle at i / 2) / |x_j - x_i| for both neighbours
    // j of i in each triangle.
    let mut weights: HashMap<(u32, u32), f64> = HashMap::with_capacity(6 * n);
    for t in triangles {
        for k in 0..3 {
            let (i, j, l) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            let (pi, pj, pl) = (positions[i as usize], positions[j as usize], positions[l as usize]);
            let half_tan = (0.5 * (pj - pi).angle_between(pl - pi)).tan();
            *weights.entry((i, j)).or_default() += half_tan / (pj - pi).length().max(f64::MIN_POSITIVE);
            *weights.entry((i, l)).or_default() += half_tan / (pl - pi).length().max(f64::MIN_POSITIVE);
        }
    }
    if count == 0 {
        return Ok(uv);
    }
    let mut triplets = Vec::with_capacity(weights.len() + count);
    let mut diagonal = vec![0.0; count];
    let mut rhs = Mat::<f64>::zeros(count, 2);
    // In a fixed order, so that the factorization, and the curve with it,
    // is the same on every run.
    let mut weights: Vec<((u32, u32), f64)> = weights.into_iter().collect();
    weights.sort_unstable_by_key(|&(edge, _)| edge);
    for &((i, j), w) in &weights {
        let row = unknown[i as usize];
        if row == u32::MAX {
            continue;
        }
        diagonal[row as usize] += w;
        if pinned[j as usize] {
            rhs[(row as usize, 0)] += w * uv[j as usize].x;
            rhs[(row as usize, 1)] += w * uv[j as usize].y;
        } else {
            triplets.push(Triplet::new(row as usize, unknown[j as usize] as usize, -w));
        }
    }
    triplets.extend(diagonal.iter().enumerate().map(|(r, &d)| Triplet::new(r, r, d)));
    let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(count, count, &triplets)
        .map_err(|e| ChartError::Solve(format!("{e:?}")))?;
    let lu = matrix.sp_lu().map_err(|e| ChartError::Solve(format!("{e:?}")))?;
    let solved = lu.solve(&rhs);
    for v in 0..n {
        if !pinned[v] {
            let r = unknown[v] as usize;
            uv[v] = DVec2::new(solved[(r, 0)], solved[(r, 1)]);
            if !uv[v].is_finite() {
                return Err(ChartError::Solve("the solve gave a point that is not a number".into()));
            }
        }
    }
    Ok(uv)
}

/// The mesh's vertices and edges with their lengths, for shortest paths.
struct VertexGraph {
    /// Neighbours of each vertex with the edge's length, mm.
    neighbours: Vec<Vec<(u32, f64)>>,
    longest_edge_mm: f64,
}

impl VertexGraph {
    fn new(surface: &SurfaceMesh) -> VertexGraph {
        let mut neighbours = vec![Vec::new(); surface.positions().len()];
        let mut longest_edge_mm: f64 = 0.0;
        for t in surface.triangles() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                let length = surface.positions()[a as usize].distance(surface.positions()[b as usize]);
                longest_edge_mm = longest_edge_mm.max(length);
                // Each edge is seen from both triangles (or once on a
                // boundary); it is listed once each way.
                if a < b || surface.faces_on_edge(a, b).len() == 1 {
                    neighbours[a as usize].push((b, length));
                    neighbours[b as usize].push((a, length));
                }
            }
        }
        VertexGraph { neighbours, longest_edge_mm }
    }

    /// Distances along edges from the nearest of `sources`.
    fn distances(&self, sources: &[u32]) -> Vec<f64> {
        self.dijkstra(sources, None).0
    }

    /// The vertices of a shortest edge path from `from` to `to`.
    fn path(&self, from: u32, to: u32) -> Option<Vec<u32>> {
        let (distance, previous) = self.dijkstra(&[from], Some(to));
        if !distance[to as usize].is_finite() {
            return None;
        }
        let mut path = vec![to];
        let mut at = to;
        while at != from {
            at = previous[at as usize];
            path.push(at);
        }
        Some(path)
    }

    fn dijkstra(&self, sources: &[u32], target: Option<u32>) -> (Vec<f64>, Vec<u32>) {
        let n = self.neighbours.len();
        let mut distance = vec![f64::INFINITY; n];
        let mut previous = vec![u32::MAX; n];
        // Distances are non-negative, so their bits order as the numbers do.
        let mut heap = BinaryHeap::new();
        for &s in sources {
            distance[s as usize] = 0.0;
            heap.push(Reverse((0u64, s)));
        }
        while let Some(Reverse((bits, v))) = heap.pop() {
            let d = f64::from_bits(bits);
            if d > distance[v as usize] {
                continue;
            }
            if Some(v) == target {
                break;
            }
            for &(w, length) in &self.neighbours[v as usize] {
                let through = d + length;
                if through < distance[w as usize] {
                    distance[w as usize] = through;
                    previous[w as usize] = v;
                    heap.push(Reverse((through.to_bits(), w)));
                }
            }
        }
        (distance, previous)
    }
}
