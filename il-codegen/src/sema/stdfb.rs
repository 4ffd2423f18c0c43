//! Interfaces of the standard function blocks of il-std, as the checker needs
//! them: inputs and outputs with their IEC names and types, read from the one
//! table of il-std ([`il_std::signature::FB_SIGNATURES`]).

use super::types::Elem;
use il_std::signature::{self as sig, FbParam};
use std::sync::OnceLock;

pub struct StdFb {
    pub name: &'static str,
    pub inputs: Vec<(&'static str, Elem)>,
    pub outputs: Vec<(&'static str, Elem)>,
}

fn params(ps: &[FbParam]) -> Vec<(&'static str, Elem)> {
    ps.iter()
        .map(|p| {
            // il-std's blocks have elementary parameters only (its table's
            // compile-time proof names each field's type).
            let e = super::types::Ty::of_std(p.ty)
                .elem()
                .unwrap_or_else(|| panic!("standard FB parameter {} : {:?}", p.name, p.ty));
            (p.name, e)
        })
        .collect()
}

fn table() -> &'static [StdFb] {
    static TABLE: OnceLock<Vec<StdFb>> = OnceLock::new();
    TABLE.get_or_init(|| {
        sig::FB_SIGNATURES
            .iter()
            .map(|f| StdFb {
                name: f.name,
                inputs: params(f.inputs),
                outputs: params(f.outputs),
            })
            .collect()
    })
}

/// Look a standard FB up by name (case-insensitive).
pub fn lookup(name: &str) -> Option<&'static StdFb> {
    table().iter().find(|f| f.name.eq_ignore_ascii_case(name))
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_block_of_the_table_is_known_with_its_types() {
        assert_eq!(super::table().len(), il_std::signature::FB_SIGNATURES.len());
        let ctud = super::lookup("ctud_lint").unwrap();
        assert_eq!(ctud.name, "CTUD_LINT");
        assert_eq!(ctud.outputs.last(), Some(&("CV", super::Elem::LINT)));
    }
}
