//! The coverage table of the differential test.

use super::*;

/// The coverage table: construct -> how many programs used it (marks that
/// are not in `CONSTRUCTS` are printed too, and fail the test: the list and
/// the generator must agree).
pub(super) fn print_coverage(count: usize, coverage: &std::collections::BTreeMap<&str, usize>) {
    println!("coverage of {count} generated programs (construct: programs using it):");
    let list = generator::coverage::CONSTRUCTS;
    let width = list.iter().map(|k| k.len()).max().unwrap_or(0);
    for k in list {
        let n = coverage.get(k).copied().unwrap_or(0);
        println!(
            "  {k:width$}  {n:>6}{}",
            if n == 0 { "  <- none" } else { "" }
        );
    }
    let stray: Vec<&&str> = coverage.keys().filter(|k| !list.contains(k)).collect();
    assert!(
        stray.is_empty(),
        "marks missing from coverage::CONSTRUCTS: {stray:?}"
    );
}
