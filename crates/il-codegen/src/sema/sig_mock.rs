// TEMPORARY stand-in for il_std::signature until the il-std branch lands.
#![allow(dead_code, clippy::upper_case_acronyms)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Class { AnyNum, AnyInt, AnyReal, AnyBit, AnyElementary, AnyString, AnyDate, Any, Bool }
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Elem { BOOL, INT, DINT, LREAL, REAL, DWORD, STRING, WSTRING }
impl Elem {
    pub fn name(self) -> &'static str { match self { Elem::BOOL => "BOOL", Elem::INT => "INT", Elem::DINT => "DINT", Elem::LREAL => "LREAL", Elem::REAL => "REAL", Elem::DWORD => "DWORD", Elem::STRING => "STRING", Elem::WSTRING => "WSTRING" } }
    pub fn from_name(n: &str) -> Option<Elem> { [Elem::BOOL, Elem::INT, Elem::DINT, Elem::LREAL, Elem::REAL, Elem::DWORD, Elem::STRING, Elem::WSTRING].into_iter().find(|e| e.name().eq_ignore_ascii_case(n)) }
    pub fn class_member(self, c: Class) -> bool { match c { Class::AnyNum => matches!(self, Elem::INT | Elem::DINT | Elem::REAL | Elem::LREAL), Class::AnyString => matches!(self, Elem::STRING | Elem::WSTRING), _ => true } }
}
pub enum ParamTy { Concrete(Elem), T(Class), Other(Class) }
pub enum Ext { Fixed, Fold, Chain, Mux }
pub struct Param { pub name: &'static str, pub ty: ParamTy }
pub struct Signature { pub name: &'static str, pub params: &'static [Param], pub ret: ParamTy, pub ext: Ext, pub doc: &'static str }
pub static SIGNATURES: &[Signature] = &[
    Signature { name: "LIMIT", params: &[Param { name: "MN", ty: ParamTy::T(Class::AnyElementary) }, Param { name: "IN", ty: ParamTy::T(Class::AnyElementary) }, Param { name: "MX", ty: ParamTy::T(Class::AnyElementary) }], ret: ParamTy::T(Class::AnyElementary), ext: Ext::Fixed, doc: "" },
    Signature { name: "MAX", params: &[Param { name: "IN1", ty: ParamTy::T(Class::AnyElementary) }, Param { name: "IN2", ty: ParamTy::T(Class::AnyElementary) }], ret: ParamTy::T(Class::AnyElementary), ext: Ext::Fold, doc: "" },
    Signature { name: "INT_TO_REAL", params: &[Param { name: "IN", ty: ParamTy::Concrete(Elem::INT) }], ret: ParamTy::Concrete(Elem::REAL), ext: Ext::Fixed, doc: "" },
];
pub fn lookup(name: &str) -> Option<&'static Signature> { SIGNATURES.iter().find(|s| s.name.eq_ignore_ascii_case(name)) }
