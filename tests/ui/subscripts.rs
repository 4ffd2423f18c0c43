// Subscript expressions and input operators on elements of arrays of blocks.
// Each case is one IL mistake in its own module.

// A constant divisor of zero in a subscript.
mod subscript_divides_by_zero { il_macros::il!(r#"
PROGRAM Main
VAR a : ARRAY[0..3] OF INT; i : INT; x : INT; END_VAR
    LD a[i MOD (2 - 2)]
    ST x
END_PROGRAM
"#); }

// An expression of literals outside the bounds once folded.
mod subscript_folded_out_of_bounds { il_macros::il!(r#"
PROGRAM Main
VAR a : ARRAY[0..3] OF INT; x : INT; END_VAR
    LD a[7 MOD 4 + 1]
    ST x
END_PROGRAM
"#); }

// INT and ULINT: no integer type holds both.
mod subscript_no_common_type { il_macros::il!(r#"
PROGRAM Main
VAR a : ARRAY[0..3] OF INT; i : INT; u : ULINT; x : INT; END_VAR
    LD a[i + u]
    ST x
END_PROGRAM
"#); }

// `S` on an element of an array of SR (its set input is S1).
mod set_on_sr_element { il_macros::il!(r#"
PROGRAM Main
VAR latch : ARRAY[0..1] OF SR; go : BOOL; i : INT; END_VAR
    LD go
    S latch[i MOD 2]
END_PROGRAM
"#); }

// `PT` (a timer's input) on an element of an array of counters.
mod timer_input_on_counter_element { il_macros::il!(r#"
PROGRAM Main
VAR c : ARRAY[0..1] OF CTU; i : INT; END_VAR
    LD T#1s
    PT c[i]
END_PROGRAM
"#); }

fn main() {}
