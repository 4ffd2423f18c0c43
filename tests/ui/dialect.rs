// Dialects: the 3rd-edition forms il! accepts by default, refused one by one
// with `std = "iec2003"`, and the partial access that is wrong in any edition.

// Dialect: a pragma under the 2nd edition.
mod pragma_strict { il_macros::il!(r#"
{attribute 'qualified_only'}
FUNCTION_BLOCK Fb
VAR
    x : INT;
END_VAR
    LD x
    ST x
END_FUNCTION_BLOCK
"#, std = "iec2003"); }

// Dialect: an INT stored into a DINT under the 2nd edition.
mod widening_strict { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    i : INT;
    d : DINT;
END_VAR
    LD i
    ST d
END_FUNCTION_BLOCK
"#, std = "iec2003"); }

// Dialect: a bit of a WORD under the 2nd edition.
mod partial_access_strict { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    status : WORD;
    ready : BOOL;
END_VAR
    LD status.3
    ST ready
END_FUNCTION_BLOCK
"#, std = "iec2003"); }

// Dialect: narrowing is never implicit (the message names DINT_TO_INT).
mod narrowing { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    i : INT;
    d : DINT;
END_VAR
    LD d
    ST i
END_FUNCTION_BLOCK
"#); }

// Dialect: bit 16 of a WORD (bits 0..15).
mod bit_beyond_width { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    status : WORD;
    ready : BOOL;
END_VAR
    LD status.16
    ST ready
END_FUNCTION_BLOCK
"#); }

// Dialect: an unknown standard.
mod unknown_standard { il_macros::il!(r#"
FUNCTION_BLOCK Fb
END_FUNCTION_BLOCK
"#, std = "iec1993"); }

fn main() {}
