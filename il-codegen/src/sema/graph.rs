//! Strongly connected components of a small directed graph (POUs calling
//! or holding each other, STRUCTs holding each other): which nodes lie on a
//! cycle, in time linear in the graph. Iterative (Kosaraju), so a chain of
//! thousands of declarations cannot overflow the stack.

/// The components of the graph `succ` (node → successors): for each node the
/// index of its component, and the members of each component (sorted).
pub(crate) fn components(succ: &[Vec<usize>]) -> (Vec<usize>, Vec<Vec<usize>>) {
    let n = succ.len();
    let mut pred: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, out) in succ.iter().enumerate() {
        for &j in out {
            pred[j].push(i);
        }
    }
    // Pass 1: finishing order of a depth-first search.
    let mut order = Vec::with_capacity(n);
    let mut seen = vec![false; n];
    for s in 0..n {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        let mut stack = vec![(s, 0usize)];
        while let Some((v, k)) = stack.pop() {
            if let Some(&w) = succ[v].get(k) {
                stack.push((v, k + 1));
                if !seen[w] {
                    seen[w] = true;
                    stack.push((w, 0));
                }
            } else {
                order.push(v);
            }
        }
    }
    // Pass 2: components on the reversed graph, in reverse finishing order.
    let mut comp = vec![usize::MAX; n];
    let mut comps: Vec<Vec<usize>> = Vec::new();
    for &s in order.iter().rev() {
        if comp[s] != usize::MAX {
            continue;
        }
        let c = comps.len();
        comp[s] = c;
        let mut members = vec![s];
        let mut todo = vec![s];
        while let Some(v) = todo.pop() {
            for &u in &pred[v] {
                if comp[u] == usize::MAX {
                    comp[u] = c;
                    members.push(u);
                    todo.push(u);
                }
            }
        }
        members.sort_unstable();
        comps.push(members);
    }
    (comp, comps)
}

/// Whether each node lies on a cycle (a component of several nodes, or a
/// node with an edge to itself).
pub(crate) fn on_cycle(succ: &[Vec<usize>]) -> Vec<bool> {
    let (comp, comps) = components(succ);
    (0..succ.len())
        .map(|v| comps[comp[v]].len() > 1 || succ[v].contains(&v))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycles_chains_and_self_loops() {
        // 0 → 1 → 2 → 0 (a cycle), 3 → 3 (a self loop), 4 → 0 (a chain into it).
        let succ = vec![vec![1], vec![2], vec![0], vec![3], vec![0]];
        assert_eq!(on_cycle(&succ), [true, true, true, true, false]);
        let (comp, comps) = components(&succ);
        assert_eq!(comps[comp[0]], [0, 1, 2]);
        assert_eq!(comps[comp[4]], [4]);
    }

    #[test]
    fn a_long_chain_does_not_overflow() {
        let n = 200_000;
        let succ: Vec<Vec<usize>> = (0..n)
            .map(|i| if i + 1 < n { vec![i + 1] } else { vec![] })
            .collect();
        assert!(on_cycle(&succ).iter().all(|c| !c));
    }
}
