//! Each IL operator of the IR names the standard function it computes (what
//! an evaluator dispatches on), the entry of il-std's table of that name.

use il_codegen::ir::BinOp;

#[test]
fn each_operator_is_the_standard_function_of_its_name() {
    use BinOp::*;
    for op in [
        And, Or, Xor, Add, Sub, Mul, Div, Mod, Gt, Ge, Eq, Ne, Le, Lt,
    ] {
        let sig = il_std::signature::lookup(op.name()).unwrap();
        assert_eq!(sig.func, op.func(), "{}", op.name());
        assert_eq!(format!("{:?}", op.func()), op.name());
    }
}
