// Literals: malformed literals and values that do not fit their type.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Literal: LD 2 then ST to a BOOL (only 0 and 1 fit a BOOL).
mod literal_2_to_bool { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    flag : BOOL;
END_VAR
    LD 2
    ST flag
END_FUNCTION_BLOCK
"#); }

// Literal: 16#FG, G is no hexadecimal digit.
mod literal_bad_hex_digit { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    w : WORD;
END_VAR
    LD 16#FG
    ST w
END_FUNCTION_BLOCK
"#); }

// Literal: T#5x, 'x' is no duration unit (d h m s ms).
mod literal_bad_time_unit { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    t : TIME;
END_VAR
    LD T#5x
    ST t
END_FUNCTION_BLOCK
"#); }

// Literal: LD 300 then ST to a SINT (range -128..127).
mod literal_out_of_range { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    small : SINT;
END_VAR
    LD 300
    ST small
END_FUNCTION_BLOCK
"#); }

// Literal: 1e5, an IEC REAL literal needs a decimal point (1.0E5).
mod literal_real_without_point { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    r : REAL;
END_VAR
    LD 1e5
    ST r
END_FUNCTION_BLOCK
"#); }

// Literal: an integer larger than any IEC integer type (LINT/ULINT).
mod literal_too_big { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : LINT;
END_VAR
    LD 99999999999999999999999
    ST n
END_FUNCTION_BLOCK
"#); }

// Literal: SINT#200, the value does not fit its own type.
mod typed_literal_out_of_range { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : SINT;
END_VAR
    LD SINT#200
    ST n
END_FUNCTION_BLOCK
"#); }

// Literal: a 14-character string stored to a STRING[5].
mod string_literal_too_long { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    s : STRING[5];
END_VAR
    LD 'motor overload'
    ST s
END_FUNCTION_BLOCK
"#); }

// Literal: a STRING literal without its closing quote.
mod string_unterminated { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    msg : STRING;
END_VAR
    LD 'motor fault
    ST msg
END_FUNCTION_BLOCK
"#); }

fn main() {}
