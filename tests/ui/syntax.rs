// Syntax errors: the IL text cannot be read (operators, comments, missing END_*), and a garbled il! input.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Syntax: LD without an operand.
mod syntax_ld_missing_operand { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
END_VAR
    LD
    ST x
END_FUNCTION_BLOCK
"#); }

// Syntax: the FUNCTION_BLOCK is never closed with END_FUNCTION_BLOCK.
mod syntax_missing_end_function_block { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
END_VAR
    LD x
    ST y
"#); }

// Syntax: a VAR block without END_VAR.
mod syntax_missing_end_var { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
    LD x
    ST y
END_FUNCTION_BLOCK
"#); }

// Syntax: a ';' line comment (vendor style); IEC 61131-3 comments are (* ... *).
mod syntax_semicolon_comment { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
END_VAR
    LD x    ; copy x
    ST y
END_FUNCTION_BLOCK
"#); }

// Syntax: a Structured Text assignment 'x := 1;' in an IL body.
mod syntax_st_statement_in_il { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
END_VAR
    x := 1;
END_FUNCTION_BLOCK
"#); }

// Syntax: a garbled operator line (LDD is no IL operator).
mod syntax_unknown_operator { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
END_VAR
    LDD x
    ST y
END_FUNCTION_BLOCK
"#); }

// Syntax: a comment opened with (* and never closed.
mod syntax_unterminated_comment { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;    (* the count
    y : INT;
END_VAR
    LD x
    ST y
END_FUNCTION_BLOCK
"#); }

// Syntax: a nested comment; IEC comments do not nest, so ' still here *)' is left over.
mod nested_comment { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    (* outer (* inner *) still here *)
    LD a
    ST q
END_FUNCTION_BLOCK
"#); }

// Syntax: NOT with an operand (NOT complements the current result and takes none; use LDN).
mod not_with_operand { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    NOT a
    ST q
END_FUNCTION_BLOCK
"#); }

// Syntax: ST into a literal (ST needs a variable).
mod st_to_literal { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
END_VAR
    LD n
    ST 5
END_FUNCTION_BLOCK
"#); }

// Macro input: a number instead of an IL string or `file = "..."`.
mod macro_input_garbled { il_macros::il!(42); }

fn main() {}
