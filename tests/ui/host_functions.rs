// Host functions: FUNCTIONs marked {extern}, whose bodies are the crate's
// Rust functions. Each case is one mistake in its own module.

// The crate does not provide the host function: rustc names it at the
// signature check the generated code holds.
mod host_missing { il_macros::il!(r#"
{extern}
FUNCTION log_value : BOOL
VAR_INPUT v : INT; END_VAR
END_FUNCTION
"#); }

// The crate's function has another signature (DINT where IL says INT).
mod host_mistyped {
    fn log_value(_ctx: &mut il_std::Cycle, v: i32) -> bool {
        v > 0
    }
    il_macros::il!(r#"
{extern}
FUNCTION log_value : BOOL
VAR_INPUT v : INT; END_VAR
END_FUNCTION
"#);
}

// Semantics: {extern} before a TYPE (it marks POUs only).
mod host_before_type { il_macros::il!(r#"
{extern}
TYPE t : INT; END_TYPE
"#); }

// A host FUNCTION_BLOCK whose body the crate does not provide: rustc names
// it at the signature check.
mod host_block_missing { il_macros::il!(r#"
{extern}
FUNCTION_BLOCK Scale
VAR_INPUT i : INT; END_VAR
VAR_OUTPUT o : INT; END_VAR
END_FUNCTION_BLOCK
"#); }

// Semantics: a host FUNCTION with instructions (its body is Rust).
mod host_with_body { il_macros::il!(r#"
{extern}
FUNCTION twice : INT
VAR_INPUT v : INT; END_VAR
    LD v
    MUL 2
    ST twice
END_FUNCTION
"#); }

fn main() {}
