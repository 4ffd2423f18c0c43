//! `widen_blocks` against the fixpoint it replaced, on random layouts.

use super::{Region, nest, widen_blocks};

/// The former fixpoint: O(R^2) per pass, repeated until nothing moves.
fn widen_fixpoint(regions: &mut [Region]) {
    let mut moved = true;
    while moved {
        moved = false;
        for b in 0..regions.len() {
            if regions[b].is_loop {
                continue;
            }
            let r = regions[b];
            if let Some(lo) = regions
                .iter()
                .filter(|s| s.lo < r.lo && r.lo < s.hi && s.hi <= r.hi)
                .map(|s| s.lo)
                .min()
            {
                regions[b].lo = lo;
                moved = true;
            }
        }
    }
}

/// xorshift64*: deterministic, no dependency.
struct Rng(u64);
impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 33) as usize % n
    }
}

/// Regions as `structure` builds them: labels at distinct positions, jumps
/// at the others, each to a random label.
fn layout(rng: &mut Rng) -> (Vec<Region>, usize) {
    let len = 2 + rng.below(40);
    let n_labels = 1 + rng.below(8);
    let mut label_pos: Vec<Option<usize>> = vec![None; n_labels];
    let mut at: Vec<Option<usize>> = vec![None; len];
    for (l, p) in label_pos.iter_mut().enumerate() {
        let q = rng.below(len);
        if at[q].is_none() {
            at[q] = Some(l);
            *p = Some(q);
        }
    }
    let (mut loop_end, mut first) = (vec![None; n_labels], vec![None; n_labels]);
    for (j, label_here) in at.iter().enumerate() {
        if label_here.is_some() || rng.below(3) == 0 {
            continue;
        }
        let l = rng.below(n_labels);
        let Some(p) = label_pos[l] else { continue };
        if p < j {
            loop_end[l] = Some(j + 1);
        } else if first[l].is_none() {
            first[l] = Some(j);
        }
    }
    let region = |label, lo, hi, is_loop| Region {
        lo,
        hi,
        label,
        is_loop,
    };
    // Loops first, then blocks, in label order: as `structure` pushes them.
    let loops = (0..n_labels).filter_map(|l| Some(region(l, label_pos[l]?, loop_end[l]?, true)));
    let blocks = (0..n_labels).filter_map(|l| Some(region(l, first[l]?, label_pos[l]?, false)));
    (loops.chain(blocks).collect(), len + 1)
}

fn key(r: Option<Vec<Region>>) -> Option<Vec<(usize, usize, usize, bool)>> {
    r.map(|v| v.iter().map(|r| (r.lo, r.hi, r.label, r.is_loop)).collect())
}

#[test]
fn sweep_equals_fixpoint() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut nested, mut moved) = (0, 0);
    for case in 0..20_000 {
        let (regions, len) = layout(&mut rng);
        let mut old = regions.clone();
        widen_fixpoint(&mut old);
        let mut new = regions.clone();
        let new = if widen_blocks(&mut new, len) {
            nest(new)
        } else {
            None
        };
        let old = nest(old);
        nested += usize::from(old.is_some());
        moved += usize::from(old.as_ref().is_some_and(|o| {
            o.iter()
                .any(|r| regions.iter().all(|s| s.lo != r.lo || s.label != r.label))
        }));
        assert_eq!(key(new), key(old), "case {case}: {regions:?}");
    }
    // The layouts must exercise both outcomes and actual moves.
    assert!(
        nested > 1_000 && moved > 100,
        "{nested} nested, {moved} moved"
    );
}
