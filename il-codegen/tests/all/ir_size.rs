//! The sizes of the checked IR's shapes, pinned with upper bounds: the IR is
//! most of the front end's peak memory (two statements per instruction), and
//! one large rare variant sets the size of every value of its enum, so a new
//! field or variant must not grow them back silently (issue 17). Boxed: the
//! rare large parts (calls, ranges, addresses).

use il_codegen::sema::ir::{Const, Expr, Loc, Op, PathElem, Place, Root, Stmt, Value};
use il_codegen::sema::types::Ty;
use std::mem::size_of;

#[test]
fn ir_shapes_stay_small() {
    let sizes = [
        ("Stmt", size_of::<Stmt>(), 1000),
        ("Op", size_of::<Op>(), 1000),
        ("Expr", size_of::<Expr>(), 1000),
        ("Value", size_of::<Value>(), 1000),
        ("Place", size_of::<Place>(), 1000),
        ("Root", size_of::<Root>(), 1000),
        ("PathElem", size_of::<PathElem>(), 1000),
        ("Const", size_of::<Const>(), 1000),
        ("Ty", size_of::<Ty>(), 1000),
        ("Loc", size_of::<Loc>(), 1000),
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
