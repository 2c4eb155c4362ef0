//! Topology descriptors (section 3.4 of the paper).
//!
//! A descriptor tells how the portals on the two sides of a piece, or of a
//! partial pattern, are connected through the material inside: one component
//! id per portal, plus counters for components closed inside and holes.
//! Descriptors are kept canonical (ids numbered by first appearance, left
//! side then right side), so equal topologies compare and hash equal.

use smallvec::SmallVec;

/// The component id of one portal. Sixteen bits: a cut across a tall
/// rectangle's second pass crosses the first pass's strips dozens of times,
/// and joining two descriptors numbers the ids of both.
pub type PortalId = u16;

/// Portal component ids of one side, top to bottom.
pub type PortalIds = SmallVec<[PortalId; 8]>;

/// How a piece or partial pattern is connected through its portals.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct TopologyDescriptor {
    left: PortalIds,
    right: PortalIds,
    /// Components with no portal left: finished, inside.
    closed_components: u16,
    /// Holes enclosed so far.
    holes: u16,
}

/// The topology of a finished loop: a descriptor joined with itself.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct LoopTopology {
    /// Connected components.
    pub components: u32,
    /// Holes in the lace, not counting the openings that loops go around.
    pub holes: u32,
    /// Components that run all the way around the loop; each of them also
    /// encloses the loop's central opening.
    pub wraps: u32,
}

impl LoopTopology {
    /// Holes of the planar result, the central openings of wrapping components included.
    pub fn planar_holes(&self) -> u32 {
        self.holes + self.wraps
    }
}

/// Union-find over a few component ids, with an integer potential per element
/// (how many times a path winds around a loop, for [`TopologyDescriptor::close_loop`]).
struct UnionFind {
    parent: SmallVec<[PortalId; 16]>,
    potential: SmallVec<[i32; 16]>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        UnionFind { parent: (0..n as PortalId).collect(), potential: SmallVec::from_elem(0, n) }
    }

    /// Root of `x` and the potential of `x` relative to it. Sets hold a
    /// handful of ids, so no path compression is needed.
    fn find(&self, x: PortalId) -> (PortalId, i32) {
        let mut root = x;
        let mut pot = 0;
        while self.parent[root as usize] != root {
            pot += self.potential[root as usize];
            root = self.parent[root as usize];
        }
        (root, pot)
    }

    /// Adds an edge meaning `potential(b) = potential(a) + w`. Returns `None`
    /// when it joins two sets, or the winding of the cycle it closes.
    fn union(&mut self, a: PortalId, b: PortalId, w: i32) -> Option<i32> {
        let (ra, pa) = self.find(a);
        let (rb, pb) = self.find(b);
        if ra == rb {
            return Some(pa + w - pb);
        }
        self.parent[rb as usize] = ra;
        self.potential[rb as usize] = pa + w - pb;
        None
    }
}

impl TopologyDescriptor {
    /// A descriptor from raw ids (any numbering) and counters; it is made canonical.
    ///
    /// ```
    /// use tracery_core::vector_brush::TopologyDescriptor;
    /// // One component touching both portals on each side: a band.
    /// let a = TopologyDescriptor::new(&[5, 5], &[5, 5], 0, 0);
    /// let b = TopologyDescriptor::new(&[0, 0], &[0, 0], 0, 0);
    /// assert_eq!(a, b);
    /// ```
    pub fn new(left: &[PortalId], right: &[PortalId], closed_components: u16, holes: u16) -> Self {
        let mut d = TopologyDescriptor {
            left: left.iter().copied().collect(),
            right: right.iter().copied().collect(),
            closed_components,
            holes,
        };
        d.canonicalize();
        d
    }

    fn canonicalize(&mut self) {
        let largest = self.left.iter().chain(self.right.iter()).copied().max().unwrap_or(0);
        let mut map: SmallVec<[PortalId; 64]> = SmallVec::from_elem(PortalId::MAX, usize::from(largest) + 1);
        let mut next: PortalId = 0;
        for id in self.left.iter_mut().chain(self.right.iter_mut()) {
            if map[*id as usize] == PortalId::MAX {
                map[*id as usize] = next;
                next += 1;
            }
            *id = map[*id as usize];
        }
    }

    /// Component ids of the left portals, top to bottom.
    pub fn left(&self) -> &[PortalId] {
        &self.left
    }

    /// Component ids of the right portals, top to bottom.
    pub fn right(&self) -> &[PortalId] {
        &self.right
    }

    /// Components already closed inside (no portal left).
    pub fn closed_components(&self) -> u32 {
        u32::from(self.closed_components)
    }

    /// Holes already enclosed.
    pub fn holes(&self) -> u32 {
        u32::from(self.holes)
    }

    /// Number of distinct components that still touch a portal.
    pub fn open_components(&self) -> u32 {
        self.left.iter().chain(self.right.iter()).map(|&id| u32::from(id) + 1).max().unwrap_or(0)
    }

    /// Whether some component joins a left portal to a right one: only
    /// then can material cross from one side to the other.
    ///
    /// ```
    /// use tracery_core::vector_brush::TopologyDescriptor;
    /// assert!(TopologyDescriptor::new(&[0, 1], &[1], 0, 0).passes_through());
    /// // Two parts, one on each side.
    /// assert!(!TopologyDescriptor::new(&[0], &[1], 0, 0).passes_through());
    /// ```
    pub fn passes_through(&self) -> bool {
        self.left.iter().any(|id| self.right.contains(id))
    }

    /// Whether no portal is left open on either side.
    pub fn is_finished(&self) -> bool {
        self.left.is_empty() && self.right.is_empty()
    }

    /// Total components, closed and open.
    pub fn components(&self) -> u32 {
        self.closed_components() + self.open_components()
    }

    /// The fewest components any extension of this can end with: open
    /// components may still all merge into one, closed ones never change.
    pub fn min_final_components(&self) -> u32 {
        self.closed_components() + self.open_components().min(1)
    }

    /// The same descriptor with counters replaced (used to forget counters a
    /// target does not care about, so that more states merge).
    pub fn with_counters(&self, closed_components: u16, holes: u16) -> Self {
        TopologyDescriptor { closed_components, holes, ..self.clone() }
    }

    /// Joins `self` on the left with `next` on the right, gluing
    /// `self.right` to `next.left` portal by portal. `None` when the portal
    /// counts differ.
    ///
    /// Gluing along a portal either merges two components or, when both sides
    /// already belong to one component, closes a loop around a new hole.
    ///
    /// ```
    /// use tracery_core::vector_brush::TopologyDescriptor;
    /// // A fork (one component opening into two portals) then a join.
    /// let split = TopologyDescriptor::new(&[], &[0, 0], 0, 0);
    /// let merge = TopologyDescriptor::new(&[0, 0], &[], 0, 0);
    /// let ring = split.join(&merge).unwrap();
    /// assert_eq!((ring.components(), ring.holes()), (1, 1));
    /// ```
    pub fn join(&self, next: &TopologyDescriptor) -> Option<TopologyDescriptor> {
        if self.right.len() != next.left.len() {
            return None;
        }
        let na = self.open_components() as usize;
        let nb = next.open_components() as usize;
        if na + nb > 255 {
            return None;
        }
        let mut uf = UnionFind::new(na + nb);
        let mut holes = u32::from(self.holes) + u32::from(next.holes);
        for (&a, &b) in self.right.iter().zip(next.left.iter()) {
            if uf.union(a, b + na as PortalId, 0).is_some() {
                holes += 1;
            }
        }
        let left: PortalIds = self.left.iter().map(|&a| uf.find(a).0).collect();
        let right: PortalIds = next.right.iter().map(|&b| uf.find(b + na as PortalId).0).collect();
        let mut open = [false; 256];
        for &id in left.iter().chain(right.iter()) {
            open[id as usize] = true;
        }
        let mut newly_closed = 0u32;
        for x in 0..(na + nb) as PortalId {
            let (root, _) = uf.find(x);
            if root == x && !open[x as usize] {
                newly_closed += 1;
            }
        }
        let closed = u32::from(self.closed_components) + u32::from(next.closed_components) + newly_closed;
        let mut d = TopologyDescriptor {
            left,
            right,
            closed_components: closed.min(u32::from(u16::MAX)) as u16,
            holes: holes.min(u32::from(u16::MAX)) as u16,
        };
        d.canonicalize();
        Some(d)
    }

    /// Closes a loop: glues the right side back onto the left side, as when a
    /// pattern along a closed curve meets its own start. `None` when the two
    /// sides have different portal counts.
    ///
    /// ```
    /// use tracery_core::vector_brush::TopologyDescriptor;
    /// // A plain band closed on itself is one ring around the loop, no lace hole.
    /// let band = TopologyDescriptor::new(&[0], &[0], 0, 0);
    /// let t = band.close_loop().unwrap();
    /// assert_eq!((t.components, t.holes, t.wraps), (1, 0, 1));
    /// // Two strips joined by one bridge: the gap between them, interrupted
    /// // once by the bridge, is a hole in the lace.
    /// let strips = TopologyDescriptor::new(&[0, 0], &[0, 0], 0, 0);
    /// assert_eq!(strips.close_loop().unwrap().holes, 1);
    /// // Two separate strips make two rings, one inside the other.
    /// let rings = TopologyDescriptor::new(&[0, 1], &[0, 1], 0, 0).close_loop().unwrap();
    /// assert_eq!((rings.components, rings.holes, rings.wraps), (2, 0, 2));
    /// ```
    pub fn close_loop(&self) -> Option<LoopTopology> {
        if self.right.len() != self.left.len() {
            return None;
        }
        let n = self.open_components() as usize;
        let mut uf = UnionFind::new(n);
        let mut cycles = 0u32;
        let mut winding_roots: SmallVec<[PortalId; 16]> = SmallVec::new();
        let mut winding_seen: SmallVec<[PortalId; 16]> = SmallVec::new();
        // Crossing the seam from the end back to the start winds once around.
        for (&r, &l) in self.right.iter().zip(self.left.iter()) {
            if let Some(winding) = uf.union(r, l, 1) {
                cycles += 1;
                if winding != 0 {
                    winding_seen.push(r);
                }
            }
        }
        for r in winding_seen {
            let root = uf.find(r).0;
            if !winding_roots.contains(&root) {
                winding_roots.push(root);
            }
        }
        let roots = (0..n as PortalId).filter(|&x| uf.find(x).0 == x).count() as u32;
        let wraps = winding_roots.len() as u32;
        Some(LoopTopology {
            components: u32::from(self.closed_components) + roots,
            holes: u32::from(self.holes) + cycles - wraps,
            wraps,
        })
    }
}
