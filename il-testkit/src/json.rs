//! Reading back, in tests, the JSON that `ilc` and the diagnostics renderer
//! write: serde_json's [`Value`], strictly (panics on malformed input and on
//! a missing member).

pub use serde_json::Value;

/// `s` as one JSON value, with nothing after it (panics otherwise).
pub fn parse(s: &str) -> Value {
    serde_json::from_str(s).unwrap_or_else(|e| panic!("not JSON ({e}): {s}"))
}

/// The member `k` of an object (panics when absent or not an object).
pub fn get<'a>(j: &'a Value, k: &str) -> &'a Value {
    j.as_object()
        .unwrap_or_else(|| panic!("not an object: {j}"))
        .get(k)
        .unwrap_or_else(|| panic!("no {k} in {j}"))
}
