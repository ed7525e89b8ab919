//! The children a traversal of the fast hierarchy has yet to visit, nearest on top.

use arrayvec::ArrayVec;

use crate::fast::hierarchy::wide_node::{WIDTH, WideNode};

/// Pending children the stack keeps in a fixed array; more spill to the heap.
const IN_PLACE: usize = 64;

/// A child waiting on the traversal stack: a node, or a leaf's triangles, and the
/// distance at which the ray enters its box.
#[derive(Clone, Copy)]
pub struct Pending {
    /// For a node, its index; for a leaf, its first triangle group.
    pub child: u32,
    /// How many triangles a leaf holds; 0 for a node.
    pub count: u32,
    /// Where the ray enters the child's box.
    pub entry: f32,
}

impl Pending {
    /// The root, entered from the ray's start.
    pub const ROOT: Pending = Pending {
        child: 0,
        count: 0,
        entry: 0.0,
    };

    /// Child `lane` of `node`, entered at `entry`.
    #[inline]
    fn of(node: &WideNode, lane: usize, entry: f32) -> Pending {
        Pending {
            child: node.child[lane],
            count: node.count[lane],
            entry,
        }
    }
}

/// The children waiting to be visited, the next on top.
#[derive(Default)]
pub struct Stack {
    /// The first `IN_PLACE` entries, in place (nothing to allocate or clear per
    /// ray).
    entries: ArrayVec<Pending, IN_PLACE>,
    /// Entries beyond the first `IN_PLACE`, for deep trees.
    spilled: Vec<Pending>,
}

impl Stack {
    /// Puts `pending` on top, in the array while it has room.
    #[inline]
    pub fn push(&mut self, pending: Pending) {
        if let Err(full) = self.entries.try_push(pending) {
            self.spilled.push(full.element());
        }
    }

    /// The entry on top of the array, or a spilled one once the array is empty.
    /// After a spill the order is no longer strictly last-in first-out, which costs
    /// at most some culling, never a hit: every pending child is still visited.
    #[inline]
    pub fn pop(&mut self) -> Option<Pending> {
        self.entries.pop().or_else(|| self.spilled.pop())
    }

    /// Pushes every child of `node` whose bit is set in `mask`, in no order: for a
    /// search that stops at the first hit it finds.
    #[inline]
    pub fn push_all(&mut self, node: &WideNode, mask: u32) {
        for lane in Bits(mask) {
            self.push(Pending::of(node, lane, 0.0));
        }
    }

    /// Of the children of `node` whose bit is set in `mask`, entered at `entry`,
    /// returns the nearest, to be visited next, and pushes the others, the nearer
    /// ones last so that they are popped first. One and two children, the most
    /// frequent cases, are handled without sorting. The child visited next is
    /// given the entry 0: its box has just passed the test against the current
    /// limit, which no hit can lower before it is visited, so its own entry is not
    /// read.
    #[inline(always)]
    pub fn push_all_but_nearest(
        &mut self,
        node: &WideNode,
        mask: u32,
        entry: [f32; WIDTH],
    ) -> Option<Pending> {
        let pending = |lane: usize| Pending::of(node, lane, entry[lane]);
        let next = |lane: usize| Pending::of(node, lane, 0.0);
        let mut lanes = Bits(mask);
        let first = lanes.next()?;
        let Some(second) = lanes.next() else {
            return Some(next(first));
        };
        if lanes.0 == 0 {
            let (near, far) = if entry[first] <= entry[second] {
                (first, second)
            } else {
                (second, first)
            };
            self.push(pending(far));
            return Some(next(near));
        }
        let (keys, count) = farthest_first(mask, &entry);
        for &key in &keys[..count - 1] {
            self.push(pending(lane_of(key)));
        }
        Some(next(lane_of(keys[count - 1])))
    }
}

/// The lanes set in `mask` as sort keys ordered by `entry`, farthest first, and
/// how many there are: an insertion sort of keys that hold an entry's bits with the
/// lane in the lowest three ([`lane_of`]). Entries are never negative, and the
/// bits of non-negative floats are in the same order as the floats; the three bits
/// taken for the lane only blur the order of entries within eight floats of each
/// other.
#[inline(always)]
fn farthest_first(mask: u32, entry: &[f32; WIDTH]) -> ([u32; WIDTH], usize) {
    let mut keys = [0; WIDTH];
    let mut count = 0;
    for lane in Bits(mask) {
        let key = (entry[lane].to_bits() & !7) | lane as u32;
        let mut at = count;
        while at > 0 && keys[at - 1] < key {
            keys[at] = keys[at - 1];
            at -= 1;
        }
        keys[at] = key;
        count += 1;
    }
    (keys, count)
}

/// The lane held in a key of [`farthest_first`].
#[inline(always)]
fn lane_of(key: u32) -> usize {
    (key & 7) as usize
}

/// The set bits of a mask, lowest first.
pub struct Bits(pub u32);

impl Iterator for Bits {
    type Item = usize;

    #[inline]
    fn next(&mut self) -> Option<usize> {
        (self.0 != 0).then(|| {
            let bit = self.0.trailing_zeros() as usize;
            self.0 &= self.0 - 1;
            bit
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn children_are_ordered_farthest_first() {
        let entry = [5.0, 0.0, 2.5, 9.0, 1.0, 7.0, 3.0, 2.0];
        let (keys, count) = farthest_first(0b1110_1101, &entry);
        let order: Vec<usize> = keys[..count].iter().map(|&k| lane_of(k)).collect();
        assert_eq!(order, [3, 5, 0, 6, 2, 7]);
    }
}
