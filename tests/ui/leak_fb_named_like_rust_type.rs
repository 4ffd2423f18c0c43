// Legal IL that the checker accepts but whose generated Rust does not compile:
// a FUNCTION_BLOCK named `i16` (a legal IEC identifier) shadows Rust's i16,
// the type the generated code uses for INT. Expected: it compiles (or an IL
// diagnostic); a Rust error must never leak through.
il_macros::il!(r#"
FUNCTION_BLOCK i16
VAR_OUTPUT
    n : INT;
END_VAR
    LD 3
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {}
