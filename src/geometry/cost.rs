//! What a ray costs: the boxes and triangles it was tested against, counted on the
//! thread that traces it, for the image `--aov cost` (`src/inspect/`). The slab test
//! counts each box, the search among a leaf's triangles counts them; spheres are all
//! tested, every time. One count per box or leaf, not per triangle, so that counting
//! costs the renderer next to nothing.

use std::cell::Cell;

/// The tests one ray took to find its nearest hit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cost {
    /// Bounding boxes tested (the slab test).
    pub boxes: u64,
    /// Triangles tested.
    pub triangles: u64,
    /// Spheres tested: the course tests every sphere for every ray.
    pub spheres: u64,
}

impl Cost {
    /// All the tests: boxes, triangles and spheres alike.
    pub fn tests(&self) -> u64 {
        self.boxes + self.triangles + self.spheres
    }
}

thread_local! {
    /// The tests counted on this thread since [`measure`] last started counting.
    static COUNTED: Cell<Cost> = const { Cell::new(Cost { boxes: 0, triangles: 0, spheres: 0 }) };
}

/// Counts one bounding box tested.
#[inline]
pub fn count_box() {
    add(|cost| cost.boxes += 1);
}

/// Counts `n` triangles tested.
#[inline]
pub fn count_triangles(n: usize) {
    add(|cost| cost.triangles += n as u64);
}

/// Changes this thread's count by `count`.
#[inline]
fn add(count: impl FnOnce(&mut Cost)) {
    COUNTED.with(|c| {
        let mut cost = c.get();
        count(&mut cost);
        c.set(cost);
    });
}

/// What `work` returns and the tests it counted on this thread.
pub fn measure<T>(work: impl FnOnce() -> T) -> (T, Cost) {
    COUNTED.with(|c| c.set(Cost::default()));
    let value = work();
    (value, COUNTED.with(Cell::get))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_only_what_the_work_tested() {
        count_box();
        let ((), cost) = measure(|| {
            count_box();
            count_triangles(2);
        });
        assert_eq!(
            cost,
            Cost {
                boxes: 1,
                triangles: 2,
                spheres: 0
            }
        );
        assert_eq!(cost.tests(), 3);
    }
}
