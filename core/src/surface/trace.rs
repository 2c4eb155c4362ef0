//! A curve on a surface through picked points: a centripetal Catmull-Rom
//! spline through them on the chart's disk (or about a hole of it, see
//! [`SplineDomain`]), sampled finely enough that no
//! step is longer than asked on the surface, plus a point wherever it
//! crosses a mesh edge, all mapped back through their triangles. So every
//! segment of the curve lies inside one triangle of the mesh: on the
//! surface exactly, not on a chord through it.

use glam::{DVec2, DVec3};

use super::{Chart, SplineDomain, SurfaceMesh, SurfacePoint};

/// Why a curve could not be traced.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TraceError {
    /// The spline leaves the part of the mesh that was laid flat.
    #[error(
        "the curve between points {from} and {to} leaves the part of the surface around the points; pick points closer together"
    )]
    LeavesChart {
        /// From this point (from 1).
        from: usize,
        /// To this one.
        to: usize,
    },
    /// The spline runs through a hole of the chart that was closed for the
    /// flattening (a hole in the mesh, or the far end of a ring).
    #[error(
        "the curve between points {from} and {to} crosses a hole in the surface or runs off its edge; pick points around it"
    )]
    CrossesHole {
        /// From this point (from 1).
        from: usize,
        /// To this one.
        to: usize,
    },
}

/// A curve lying on a surface.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SurfaceCurve {
    /// Points on the surface, mm; consecutive points share a triangle.
    pub points_mm: Vec<DVec3>,
    /// The surface's smooth normal at each point.
    pub normals: Vec<DVec3>,
    /// Whether the curve closes (the last point joins the first).
    pub closed: bool,
}

impl SurfaceCurve {
    /// Length along the surface, mm (the closing segment included).
    pub fn length_mm(&self) -> f64 {
        let open: f64 = self.points_mm.windows(2).map(|w| w[0].distance(w[1])).sum();
        match (self.closed, self.points_mm.first(), self.points_mm.last()) {
            (true, Some(a), Some(b)) => open + a.distance(*b),
            _ => open,
        }
    }
}

/// Most spline samples between two picked points: past this the points
/// are so far apart on the disk that the chart is the wrong tool.
const MAX_SAMPLES_PER_SPAN: usize = 1 << 16;

/// Traces the spline through `points` (in order; back to the first when
/// `closed`) on `chart`, with no step longer than `step_mm` on the surface
/// between edge crossings.
pub fn trace(
    surface: &SurfaceMesh,
    chart: &Chart,
    points: &[SurfacePoint],
    closed: bool,
    step_mm: f64,
) -> Result<SurfaceCurve, TraceError> {
    let n = points.len();
    let spans = if closed { n } else { n - 1 };
    let disk: Vec<DVec2> = points
        .iter()
        .enumerate()
        .map(|(k, p)| chart.to_disk(p).ok_or(TraceError::LeavesChart { from: k + 1, to: k + 1 }))
        .collect::<Result<_, _>>()?;
    let domain = SplineDomain::for_curve(chart, &disk, closed);
    let controls = domain.controls(&disk);
    // Ends of an open curve are extended by reflection, so the spline
    // starts and stops heading at its neighbour; a closed one's controls
    // repeat, a period further on each time round.
    let control = |i: isize| -> DVec2 {
        if closed {
            controls[i.rem_euclid(n as isize) as usize] + domain.period() * i.div_euclid(n as isize) as f64
        } else if i < 0 {
            2.0 * controls[0] - controls[1.min(n - 1)]
        } else if i as usize >= n {
            2.0 * controls[n - 1] - controls[n.saturating_sub(2)]
        } else {
            controls[i as usize]
        }
    };
    let mut curve = SurfaceCurve { closed, ..SurfaceCurve::default() };
    let mut at: Option<(u32, DVec2)> = None;
    for span in 0..spans {
        let fail_leave = TraceError::LeavesChart { from: span + 1, to: (span + 1) % n + 1 };
        let fail_hole = TraceError::CrossesHole { from: span + 1, to: (span + 1) % n + 1 };
        let i = span as isize;
        let segment = CatmullRom::new(control(i - 1), control(i), control(i + 1), control(i + 2));
        let chord_mm = points[span].position_mm.distance(points[(span + 1) % n].position_mm);
        let samples = ((4.0 * chord_mm / step_mm).ceil() as usize).clamp(8, MAX_SAMPLES_PER_SPAN);
        for k in 0..=samples {
            if k == 0 && span > 0 {
                continue;
            }
            let p = domain.to_disk(segment.at(k as f64 / samples as f64));
            match at {
                None => {
                    let (t, _) = chart.locate(p).ok_or(fail_leave.clone())?;
                    at = Some((t, p));
                    push(&mut curve, surface, chart, t, p).ok_or(fail_hole.clone())?;
                }
                Some((t, from)) => {
                    let t = walk(surface, chart, &mut curve, t, from, p, &fail_leave, &fail_hole)?;
                    at = Some((t, p));
                }
            }
        }
    }
    if closed && curve.points_mm.len() > 1 {
        // The last sample is the first point again.
        let last = curve.points_mm.len() - 1;
        if curve.points_mm[last].distance(curve.points_mm[0]) < SAME_POINT_MM {
            curve.points_mm.pop();
            curve.normals.pop();
        }
    }
    Ok(curve)
}

/// Points closer than this are one, mm.
const SAME_POINT_MM: f64 = 1e-9;

/// Walks from `from` (in chart triangle `t`) to `to` on the disk, adding a
/// point at every edge crossed and at `to`; returns the triangle of `to`.
#[allow(clippy::too_many_arguments)]
fn walk(
    surface: &SurfaceMesh,
    chart: &Chart,
    curve: &mut SurfaceCurve,
    mut t: u32,
    mut from: DVec2,
    to: DVec2,
    fail_leave: &TraceError,
    fail_hole: &TraceError,
) -> Result<u32, TraceError> {
    let mut entered_over: Option<(u32, u32)> = None;
    for _ in 0..chart.triangle_count() + 1 {
        let at_to = chart.barycentric(t, to);
        if at_to.iter().all(|&c| c >= -1e-12) {
            push(curve, surface, chart, t, to).ok_or(fail_hole.clone())?;
            return Ok(t);
        }
        let at_from = chart.barycentric(t, from);
        let corners = chart.corners(t);
        // The edge opposite corner k is left where its coordinate reaches 0
        // first along the way.
        let exit = (0..3)
            .filter(|&k| at_to[k] < 0.0)
            .filter(|&k| {
                let edge = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
                Some((edge.0.min(edge.1), edge.0.max(edge.1))) != entered_over
            })
            .map(|k| (k, (at_from[k].max(0.0) / (at_from[k].max(0.0) - at_to[k])).clamp(0.0, 1.0)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let Some((k, s)) = exit else {
            // Only the edge it came in by points away: it is at `to` within rounding.
            push(curve, surface, chart, t, to).ok_or(fail_hole.clone())?;
            return Ok(t);
        };
        let crossing = from + (to - from) * s;
        push(curve, surface, chart, t, crossing).ok_or(fail_hole.clone())?;
        let (a, b) = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
        let (Some(ma), Some(mb)) = (chart.mesh_vertex(a), chart.mesh_vertex(b)) else {
            return Err(fail_hole.clone());
        };
        let face = chart.face(t);
        let next = surface
            .faces_on_edge(ma, mb)
            .iter()
            .copied()
            .find(|&f| Some(f) != face)
            .and_then(|f| chart.chart_triangle(f))
            .ok_or(fail_leave.clone())?;
        entered_over = Some((a.min(b), a.max(b)));
        t = next;
        from = crossing;
    }
    Err(fail_leave.clone())
}

/// Adds the surface point at `p` on the disk in chart triangle `t`;
/// `None` if `t` closes a hole.
fn push(curve: &mut SurfaceCurve, surface: &SurfaceMesh, chart: &Chart, t: u32, p: DVec2) -> Option<()> {
    let face = chart.face(t)?;
    let raw = chart.barycentric(t, p);
    // Rounding may put a point a hair outside its triangle.
    let clamped = raw.map(|c| c.max(0.0));
    let sum: f64 = clamped.iter().sum();
    let barycentric = clamped.map(|c| c / sum);
    let point = surface.point(face, barycentric);
    if curve.points_mm.last().is_some_and(|last| last.distance(point) < SAME_POINT_MM) {
        return Some(());
    }
    curve.points_mm.push(point);
    curve.normals.push(surface.normal(face, barycentric));
    Some(())
}

/// One span of a centripetal Catmull-Rom spline (Barry and Goldman's
/// pyramid), which neither cusps nor loops between its points.
struct CatmullRom {
    p: [DVec2; 4],
    t: [f64; 4],
}

impl CatmullRom {
    fn new(p0: DVec2, p1: DVec2, p2: DVec2, p3: DVec2) -> CatmullRom {
        // Knots spaced by the square root of the distance; a floor keeps
        // repeated points apart.
        let gap = |a: DVec2, b: DVec2| a.distance(b).sqrt().max(1e-12);
        let t1 = gap(p0, p1);
        let t2 = t1 + gap(p1, p2);
        let t3 = t2 + gap(p2, p3);
        CatmullRom { p: [p0, p1, p2, p3], t: [0.0, t1, t2, t3] }
    }

    /// The point at `s` in [0, 1] from `p1` to `p2`.
    fn at(&self, s: f64) -> DVec2 {
        let [p0, p1, p2, p3] = self.p;
        let [t0, t1, t2, t3] = self.t;
        let t = t1 + (t2 - t1) * s;
        let lerp = |a: DVec2, b: DVec2, ta: f64, tb: f64| a + (b - a) * ((t - ta) / (tb - ta));
        let a1 = lerp(p0, p1, t0, t1);
        let a2 = lerp(p1, p2, t1, t2);
        let a3 = lerp(p2, p3, t2, t3);
        let b1 = lerp(a1, a2, t0, t2);
        let b2 = lerp(a2, a3, t1, t3);
        lerp(b1, b2, t1, t2)
    }
}
