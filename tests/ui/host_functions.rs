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

// Semantics: {extern} before a PROGRAM (it marks FUNCTIONs only).
mod host_before_program { il_macros::il!(r#"
{extern}
PROGRAM P
VAR x : INT; END_VAR
    LD x
    ST x
END_PROGRAM
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
