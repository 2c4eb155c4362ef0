//! Disjoint sets (union–find with path halving): which of `n` things are
//! joined, for the shells of a mesh, flaws near each other and vertices
//! welded together.

/// `n` things, each in a set of its own until joined.
///
/// ```
/// use tracery_core::disjoint_sets::DisjointSets;
/// let mut sets = DisjointSets::new(4);
/// assert!(sets.join(0, 1));
/// assert!(sets.join(3, 1));
/// assert!(!sets.join(0, 3));
/// assert_eq!(sets.find(3), sets.find(0));
/// assert_ne!(sets.find(2), sets.find(0));
/// ```
#[derive(Clone, Debug)]
pub struct DisjointSets {
    parent: Vec<usize>,
}

impl DisjointSets {
    /// `n` things, each alone.
    pub fn new(n: usize) -> DisjointSets {
        DisjointSets { parent: (0..n).collect() }
    }

    /// The representative of `x`'s set: the smallest index ever joined to
    /// it, so that representatives are stable whatever the order of joins.
    pub fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    /// Joins the sets of `a` and `b`; whether they were apart.
    pub fn join(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        self.parent[ra.max(rb)] = ra.min(rb);
        ra != rb
    }
}
