//! "Did you mean": the known name closest to one that is not known, for the
//! checker's messages and for the tools that take names from users (`ilc
//! run --set`, the interpreter's paths).

/// Names longer than this get no suggestion (IEC identifiers in real
/// programs are far shorter).
const MAX_LEN: usize = 64;

/// Case-insensitive "did you mean": the closest of `candidates` to `name`,
/// if one is close enough (an edit distance of at most a third of the
/// longer name, at least 1).
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    // Bounded: no suggestion for a name no one types (a damaged or hostile
    // file), and no distance computed for a candidate whose length alone
    // rules it out, so the search is linear in the candidates.
    if name.len() > MAX_LEN {
        return None;
    }
    let up = name.to_ascii_uppercase();
    // Rank by edit distance (optimal string alignment: a swap of two
    // neighbours counts once), then prefer a candidate that extends the
    // name (`Q` → `Q1`), then the closest length.
    let mut best: Option<((usize, bool, usize), &str)> = None;
    for c in candidates {
        crate::step_counter::add(1);
        let limit = (up.len().max(c.len()) / 3).max(1);
        if up.len().abs_diff(c.len()) > limit || c.len() > MAX_LEN {
            continue;
        }
        let cu = c.to_ascii_uppercase();
        if cu == up {
            continue;
        }
        crate::step_counter::add((up.len() * cu.len()) as u64);
        let d = strsim::osa_distance(&up, &cu);
        let rank = (
            d,
            !(cu.starts_with(&up) || up.starts_with(&cu)),
            up.len().abs_diff(cu.len()),
        );
        if d <= limit && best.is_none_or(|(b, _)| rank < b) {
            best = Some((rank, c));
        }
    }
    best.map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::suggest;

    #[test]
    fn transpositions_prefixes_and_limits() {
        assert_eq!(suggest("spede", ["speed", "spread"]), Some("speed"));
        assert_eq!(suggest("strat", ["start", "stop"]), Some("start"));
        assert_eq!(suggest("Q", ["S1", "R", "Q1"]), Some("Q1"));
        assert_eq!(suggest("LDD", ["ADD", "LD"]), Some("LD"));
        assert_eq!(suggest("motor", ["valve"]), None);
    }
}
