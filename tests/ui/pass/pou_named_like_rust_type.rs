// A FUNCTION_BLOCK named `i16` (a legal IEC identifier) must not hide Rust's
// i16 in the generated code: the struct is emitted as `i16_`.
il_macros::il!(r#"
FUNCTION_BLOCK i16
VAR_OUTPUT
    n : INT;
END_VAR
    LD 3
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {
    let mut ctx = il_std::Cycle::new();
    let mut b = i16_::default();
    b.call(&mut ctx);
    let n: i16 = b.n;
    assert_eq!(n, 3);
}
