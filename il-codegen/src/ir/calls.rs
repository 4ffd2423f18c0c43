//! The calls of the checked IR, boxed in [`super::Expr`] and [`super::Op`]: rare and
//! large, inline they would set the size of every expression and statement.

use super::types::Ty;
use super::{Condition, Place, StdCall, Value, Widen};

/// A call of a user FUNCTION: arguments in declaration order of its
/// inputs; `out_types` are all its outputs, `outputs` the ones read with
/// `=>` (index into `out_types`, target, complemented).
#[derive(Clone, Debug, PartialEq)]
pub struct UserCall {
    /// EN := value: run only when TRUE.
    pub en: Option<Value>,
    /// Places bound to the VAR_IN_OUTs, in their declaration order: each
    /// is read before the call and written back after it, in this order
    /// (the same as passing it by reference: a FUNCTION has no other way
    /// to reach the place).
    pub inouts: Vec<Place>,
    /// Index of the implicit ENO among the outputs, if the function sets ENO.
    pub eno: Option<usize>,
    /// The FUNCTION's result type.
    pub ret: Ty,
    /// The FUNCTION's name, as declared.
    pub name: String,
    /// The input arguments, in declaration order of its inputs.
    pub args: Vec<Value>,
    /// The types of all its VAR_OUTPUTs, in declaration order.
    pub out_types: Vec<Ty>,
    /// The outputs read with `=>`: (index into `out_types`, target,
    /// complemented, widened to the target's type).
    pub outputs: Vec<(usize, Place, bool, Option<Widen>)>,
}

/// A call of an il-std function.
#[derive(Clone, Debug, PartialEq)]
pub struct StdFnCall {
    /// The function's entry in il-std's table: its name, its rounding
    /// ([`il_std::signature::Signature::rounding`]) and its documentation.
    pub sig: &'static il_std::signature::Signature,
    /// `EN := value` of a formal call: evaluated only when TRUE, else the
    /// result is the type's default (and `ENO =>` targets get FALSE).
    pub en: Option<Value>,
    /// Which il-std function, and how to call it.
    pub call: StdCall,
    /// The arguments, CR first for the operator form.
    pub args: Vec<Value>,
    /// Their types, one per argument.
    pub arg_types: Vec<Ty>,
    /// The result type.
    pub ret: Ty,
    /// The runtime fault the call may record, from the signature table
    /// ([`il_std::signature::Signature::fault_for`] of the argument types):
    /// the emitter calls the `*_checked` companion and records it, the
    /// interpreter checks the same condition.
    pub fault: Option<il_std::FaultKind>,
}

/// Call an FB instance after setting inputs; then copy outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct FbCall {
    /// The instance.
    pub inst: Place,
    /// Inputs set before the call, with their values.
    pub inputs: Vec<(Member, Value)>,
    /// Outputs copied after the call: (output, target, complemented,
    /// widened to the target's type).
    pub outputs: Vec<(Member, Place, bool, Option<Widen>)>,
    /// Places bound to the FB's VAR_IN_OUTs, in their declaration order,
    /// each with the index of its VAR_IN_OUT in the FB's
    /// [`super::CheckedPou::vars`].
    pub inouts: Vec<(u32, Place)>,
    /// Some in-out is bound to a place under the instance's own root
    /// (`CAL b(x := i, io := b.x)`): in-outs are references, so each is
    /// read after the inputs are set and sees them.
    pub inouts_in_instance: bool,
    /// The FB's (non-located) VAR_EXTERNALs, in declaration order: the
    /// caller passes its own externals of the same names.
    /// (A boxed slice: built once, and 8 bytes smaller than a `Vec` in
    /// every checked CAL.)
    pub externals: Box<[PassedExternal]>,
    /// `CALC` / `CALCN`: call only when the condition holds.
    pub cond: Condition,
}

/// A VAR_EXTERNAL of a called FB, which the caller passes down from its own.
#[derive(Clone, Debug, PartialEq)]
pub struct PassedExternal {
    /// As declared (the same name in the caller and the FB).
    pub name: String,
    /// The FB declares it CONSTANT: a shared reference suffices.
    pub constant: bool,
    /// Its index in the caller's [`super::CheckedPou::vars`].
    pub caller: u32,
    /// Its index in the FB's [`super::CheckedPou::vars`].
    pub callee: u32,
}

/// A member of a function block instance or a structure, as the checker
/// resolved it: the name the emitter prints (the Rust field) and the index
/// an interpreter reaches it by, so that no consumer looks a name up again:
/// the index into a user FB's (or PROGRAM's) [`super::CheckedPou::vars`],
/// the position in il-std's table of a standard block (its inputs, then its
/// outputs: [`il_std::signature::FbSignature`]), or the position among a
/// STRUCT's fields ([`super::TypeDef::Struct`]).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Member {
    /// As declared.
    pub name: Box<str>,
    /// As above.
    pub index: u32,
}

impl std::fmt::Display for Member {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name)
    }
}
