//! What a resolved name names ([`Key`]), apart from the body checker that
//! notes them, so that the declaration resolver can name type keys without
//! importing the checker.

use crate::ast::TypeSpec;

/// What a resolved name names, by upper-case names (what the checker has
/// at hand where it resolves).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Key {
    Pou(String),
    /// Variable `index` of a POU ([`PouSig::vars`]).
    Var(String, usize),
    /// Label `index` of a POU (in order of first definition).
    Label(String, usize),
    Type(String),
    /// Field `index` of a STRUCT.
    Field(String, usize),
    /// Value `index` of an enumeration.
    EnumValue(String, usize),
    Config(String),
    /// (configuration, name)
    Resource(String, String),
    Global(String, String),
    Instance(String, String),
    /// By il-std's spelling.
    StdFn(&'static str),
    StdFb(&'static str),
    StdMember(&'static str, &'static str),
}

/// The key of a type name where it is written in a declaration.
pub(crate) fn type_key(names: &crate::sema::env::Names, spec: &TypeSpec) -> Option<Key> {
    let TypeSpec::Named(id) = spec else {
        return None;
    };
    let key = id.key();
    if let Some(fb) = il_std::signature::lookup_fb(&key) {
        return Some(Key::StdFb(fb.name));
    }
    if names.types.contains_key(&key) {
        return Some(Key::Type(key));
    }
    names.pous.contains_key(&key).then_some(Key::Pou(key))
}
