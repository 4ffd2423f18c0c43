//! The sizes of the checked IR's shapes, pinned with upper bounds: the IR is
//! most of the front end's peak memory (about a statement per instruction), and
//! one large rare variant sets the size of every value of its enum, so a new
//! field or variant must not grow them back silently (issue 17). Boxed: the
//! rare large parts (calls, ranges, addresses); in tables of the POU, by
//! index: the places values read and statements write, the CR's types.
//! The bounds are today's sizes on 64-bit targets: shrinking is welcome
//! (lower the bound), growing needs a reason (issue 17: before boxing, a
//! `Stmt` was 448 bytes, a `Value` and a `Place` 160; before types became
//! two words (array types boxed, names shared) and integer constants 64-bit
//! values with a sign, 208, 48 and 88; before values named the CR, saved
//! slots and places by index into per-POU tables, 120, 32 and 64; before
//! a binary operation kept the elementary type only, 72).

use il_codegen::ir::types::Ty;
use il_codegen::ir::{Const, Expr, Loc, Op, PathElem, Place, Root, Stmt, Value};
use std::mem::size_of;

#[test]
fn ir_shapes_stay_small() {
    let sizes = [
        ("Stmt", size_of::<Stmt>(), 56),
        ("Op", size_of::<Op>(), 48),
        ("Expr", size_of::<Expr>(), 40),
        ("Value", size_of::<Value>(), 16),
        ("Place", size_of::<Place>(), 64),
        ("Root", size_of::<Root>(), 16),
        ("PathElem", size_of::<PathElem>(), 48),
        ("Const", size_of::<Const>(), 16),
        ("Ty", size_of::<Ty>(), 16),
        ("Loc", size_of::<Loc>(), 40),
    ];
    for (name, size, bound) in sizes {
        println!("size_of::<{name}>() = {size} (bound {bound})");
    }
    for (name, size, bound) in sizes {
        assert!(
            size <= bound,
            "size_of::<{name}>() is {size}, bound {bound}"
        );
    }
}

/// The syntax tree's body is the other large part of the peak (one
/// statement per instruction, alive while the IR is built): the same kind
/// of bounds for its shapes. Boxed: an enumeration literal's two names, a
/// literal's type prefix, a deferred operation's first operand, a CAL's
/// arguments; an integer literal is an `IntValue`, not an `i128` (issue 17:
/// an instruction was 176 bytes, then 144, then 96 before names became
/// boxed `str`s, a reference's steps a boxed slice and its span computed).
#[test]
fn syntax_shapes_stay_small() {
    use il_codegen::ast::{
        CallArgs, DirectAddress, Ident, Instr, InstrKind, LitKind, Literal, Operand,
        Stmt as AstStmt, VarRef,
    };
    let sizes = [
        ("ast::Stmt", size_of::<AstStmt>(), 80),
        ("Instr", size_of::<Instr>(), 80),
        ("InstrKind", size_of::<InstrKind>(), 64),
        ("CallArgs", size_of::<CallArgs>(), 32),
        ("Operand", size_of::<Operand>(), 48),
        ("VarRef", size_of::<VarRef>(), 40),
        ("Ident", size_of::<Ident>(), 24),
        ("DirectAddress", size_of::<DirectAddress>(), 40),
        ("Literal", size_of::<Literal>(), 48),
        ("LitKind", size_of::<LitKind>(), 32),
    ];
    for (name, size, bound) in sizes {
        println!("size_of::<{name}>() = {size} (bound {bound})");
        assert!(
            size <= bound,
            "size_of::<{name}>() is {size}, bound {bound}"
        );
    }
}
