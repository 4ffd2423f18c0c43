// Accepted IL compiles: keywords and names in any case, operator names (R1,
// IN, PV) as variable names, as the standard's STACK_INT does.
use il_std::Cycle;

il_macros::il!(r#"
function_block Latch
var_input
    Set : BOOL;
    R1 : BOOL;
    IN : INT;
end_var
var_output
    Out : BOOL;
    PV : INT;
end_var
    ld SET
    or out
    andn r1
    st OUT
    Ld in
    St pv
end_function_block
"#);

fn main() {
    let mut ctx = Cycle::new();
    let mut l = Latch::default();
    l.Set = true;
    l.IN = 7;
    l.call(&mut ctx);
    assert!(l.Out);
    assert_eq!(l.PV, 7);
}
