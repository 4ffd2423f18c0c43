//! The front end's diagnostic codes (IL0001..IL0099), next to no stage's
//! code in particular: the lexer, the grammar actions and the parse-error
//! messages all report them.

crate::diag::codes::codes! {
    BAD_CHAR = "IL0001", "a character that has no meaning in IL",
        "The text contains a character that IEC 61131-3 Instruction List does not use outside comments and strings.\n\n    LD x @ 1      (* `@` is not IL *)\n\nRemove it, or put it in a comment (* ... *).";
    UNTERMINATED_COMMENT = "IL0002", "a comment that is never closed",
        "A comment starts with `(*` and ends with `*)`. Comments do not nest.\n\n    (* start of a comment\n    LD x\n\nClose the comment with `*)`.";
    MISSING_OPERAND = "IL0003", "an operator without its operand",
        "LD, ST, S, R, AND, ADD, GT ..., and the FB input operators (PV, IN ...) need an operand.\n\n    LD          (* load what? *)\n\nWrite `LD x`.";
    NO_OPERAND = "IL0004", "an operator that takes no operand was given one",
        "NOT complements the current result and RET/RETC/RETCN return; they take no operand.\n\n    NOT x       (* wrong *)\n\nTo load the complement of `x` write `LDN x`; to complement the current result write `NOT` alone.";
    SYNTAX = "IL0005", "an instruction line that cannot be read",
        "The line does not follow the form `label: OPERATOR operand` of an IL instruction.\n\n    LD x y      (* two operands *)\n\nWrite one instruction per line with one operand (or a comma list for a function).";
    MISSING_LABEL = "IL0006", "a jump without a label",
        "JMP, JMPC and JMPCN need the label to jump to.\n\n    JMPC        (* where to? *)\n\nWrite `JMPC done` and put `done:` before the target instruction.";
    MISSING_CAL_TARGET = "IL0007", "CAL without a function block instance",
        "CAL, CALC and CALCN call a function block instance.\n\n    CAL (IN := x)\n\nWrite `CAL timer1(IN := x, PT := T#1s)`.";
    SEMI_COMMENT = "IL0008", "a `;` comment (not IEC)",
        "Some tools accept `;` to start a comment; IEC 61131-3 does not.\n\n    LD x   ; load x\n\nWrite `LD x   (* load x *)`.";
    ST_CODE = "IL0009", "Structured Text code in an IL file",
        "Only Instruction List is supported; the POU contains a Structured Text statement such as an assignment or IF.\n\n    c := a + b;\n\nIn IL write:\n\n    LD a\n    ADD b\n    ST c\n\nThe rest of the POU is skipped.";
    SFC_CODE = "IL0010", "Sequential Function Chart elements",
        "STEP, TRANSITION and ACTION belong to SFC, which is not supported.\n\n    INITIAL_STEP start:\n    END_STEP\n\nWrite the sequence in IL with jumps and BOOL state variables. The rest of the POU is skipped.";
    ORPHAN = "IL0011", "instructions outside a PROGRAM, FUNCTION or FUNCTION_BLOCK",
        "IL instructions belong inside a program organisation unit.\n\n    LD %IX0.0\n    ST %QX0.0\n\nWrap them:\n\n    PROGRAM main\n    LD %IX0.0\n    ST %QX0.0\n    END_PROGRAM";
    DECL_AFTER_CODE = "IL0012", "declarations after the instructions",
        "All VAR ... END_VAR blocks of a POU come before its first instruction.\n\n    LD a\n    VAR b : INT; END_VAR\n\nMove the VAR block up, before `LD a`.";
    MISSING_END_VAR = "IL0013", "a VAR block without END_VAR",
        "Each VAR, VAR_INPUT, ... block ends with END_VAR.\n\n    VAR x : INT;\n    LD x\n\nAdd `END_VAR` after the last declaration.";
    MISSING_END = "IL0014", "a missing or wrong END_ keyword",
        "FUNCTION ends with END_FUNCTION, FUNCTION_BLOCK with END_FUNCTION_BLOCK, PROGRAM with END_PROGRAM, TYPE with END_TYPE, CONFIGURATION with END_CONFIGURATION.\n\n    FUNCTION_BLOCK fb\n    LD x\n    END_FUNCTION\n\nWrite `END_FUNCTION_BLOCK`.";
    PAREN = "IL0015", "an unbalanced parenthesis",
        "A deferred operation `AND(` is closed by a `)` line; an argument list `CAL fb(` is closed by `)`.\n\n    AND( x\n    OR y\n    ST z      (* the `)` is missing *)\n\nAdd the `)` line before `ST z`.";
    IN_PARENS = "IL0016", "a label, jump, CAL or RET inside parentheses",
        "Between `OP(` and its `)` only instructions that compute a value may appear.\n\n    AND(\n    JMP l\n    )\n\nMove the jump, call, return or label outside the parentheses.";
    TOO_DEEP = "IL0017", "parentheses nested too deep",
        "Deferred parentheses may nest 256 deep.\n\n    AND( AND( AND( ... (257 times)\n\nStore intermediate results in temporary variables.";
    BAD_NUMBER = "IL0018", "a malformed number or typed literal",
        "Integers are written `123`, `1_000`, `16#FF`, `2#1010`, `8#17`; reals need a decimal point: `1.5`, `1.0E-3`.\n\n    LD -12e-5     (* no `.` *)\n\nWrite `LD -12.0e-5`. Typed literals: `INT#-5`, `BOOL#1`, `REAL#1.5`.";
    BAD_DURATION = "IL0019", "a malformed duration",
        "Durations are `T#` or `TIME#` followed by numbers with units d, h, m, s, ms, us, ns; only the last may have a fraction.\n\n    LD T#25x\n\nWrite e.g. `T#25s` or `T#1h_30m`.";
    BAD_DATE = "IL0020", "a malformed date or time of day",
        "`D#2024-01-31`, `TOD#14:30:00.5`, `DT#2024-01-31-14:30:00`: the month, day, hour, minute and second must exist.\n\n    LD D#2001-13-40\n\nThere is no month 13: write a valid date.";
    BAD_STRING = "IL0021", "a malformed string",
        "Strings are `'...'` (STRING) or `\"...\"` (WSTRING) on one line, with `$` escapes: $$ $' $\" $L $N $P $R $T and $ plus hex digits.\n\n    LD 'abc\n\nClose the string: `LD 'abc'`.";
    BAD_ADDRESS = "IL0022", "a malformed direct address",
        "Direct addresses are `%I`, `%Q` or `%M`, an optional size X B W D L and dotted numbers.\n\n    LD %MF0     (* F is not an IEC size *)\n\nWrite `%MD0` and declare the variable as REAL, or `%IX0.1` for a bit.";
    DECL_SYNTAX = "IL0023", "a declaration that cannot be read",
        "Declarations have the form `a, b AT %IX0.0 : TYPE := initial;`.\n\n    VAR x : INT\n        y : BOOL; END_VAR\n\nEnd each declaration with `;`.";
    CONFIG_SYNTAX = "IL0024", "a CONFIGURATION element that cannot be read",
        "A configuration holds VAR_GLOBAL blocks, RESOURCEs, TASKs and program instances, then VAR_ACCESS and VAR_CONFIG (which belong to the configuration, not to a RESOURCE).\n\n    TASK t (CYCLE := T#10ms);\n\nTASK parameters are SINGLE, INTERVAL and PRIORITY: `TASK t (INTERVAL := T#10ms, PRIORITY := 1);`.";
    PRAGMA = "IL0025", "a pragma `{ ... }` that is never closed",
        "A pragma starts with `{` and ends with the next `}`; the compiler ignores it (it stands wherever a comment may). One that is never closed would swallow the rest of the file.\n\n    {attribute 'hide'\n    PROGRAM Main\n\nClose it: `{attribute 'hide'}`.";
    TOO_LARGE = "IL0026", "a source file over 4 GiB",
        "Source files are limited to 4 GiB. Split the program into several files.";
    RESULT_TYPE = "IL0027", "a missing or misplaced result type",
        "A FUNCTION has a result type; a FUNCTION_BLOCK or PROGRAM has none.\n\n    FUNCTION f\n\nWrite `FUNCTION f : INT`.";
    BEGIN_IL = "IL0028", "BEGIN_IL / END_IL out of place",
        "KAS-IDE wraps a body in BEGIN_IL ... END_IL: one BEGIN_IL before the first instruction, one END_IL after the last.\n\n    BEGIN_IL\n    LD x\n\nAdd `END_IL` after the last instruction.";
    UNEXPECTED_EOF = "IL0029", "the file ends in the middle of something",
        "The file ends before a construct is complete.\n\n    TYPE t : STRUCT a : INT;\n\nComplete it (here with `END_STRUCT; END_TYPE`).";
    EXTRA_TOKENS = "IL0030", "text after a complete instruction",
        "IL has one instruction per line.\n\n    LD a ST b\n\nPut `ST b` on its own line.";
    EXPECTED_INSTRUCTION = "IL0031", "a line that does not start with an operator",
        "An instruction line starts with an optional `label:` and an operator or function name.\n\n    5\n\nWrite e.g. `LD 5`.";
    NOT_IDENT = "IL0033", "a word that is not an identifier",
        "A name needs at least one letter or digit: `_` alone (or `__`, `___` ...) is no IEC identifier, and in the generated Rust it would be the wildcard pattern.\n\n    VAR _ : INT; END_VAR\n\nName it: `VAR unused : INT; END_VAR`.";
    LONG_NAME = "IL0034", "a name longer than 255 characters",
        "Names (of variables, POUs, types, labels, operators) are at most 255 characters long, as in PLCopen XML. The limit keeps every message, suggestion and generated identifier bounded on damaged or generated input.\n\n    VAR a_name_of_three_hundred_characters_... : INT; END_VAR\n\nShorten the name.";
    SNIPPET = "IL0036", "a `--snippet` file that needs declarations",
        "`ilc check/emit/run --snippet FILE` compiles a bare instruction list, as in the standard's Table 51, as the body of a PROGRAM named after the file. Without declarations, only direct addresses and literals have a meaning; every other name is listed in this one error, and a file that declares a POU is no bare list.\n\n    START: LD  start_button\n           ANDN %MX5\n           ST  %QX2\n\nWrite `LD %IX1`, or declare the names in a PROGRAM and check the file without `--snippet`.";
    HOST_MARK = "IL0037", "an `{extern}` pragma that does not stand before a POU",
        "`{extern}` marks the FUNCTION (or FUNCTION_BLOCK, or PROGRAM) that follows it as host-provided: the program declares its interface in IL and the crate around the generated code provides its body in Rust. It must stand right before the POU's keyword (only comments, other pragmas and white space between), not inside a POU or before another kind of declaration.\n\n    {extern}\n    TYPE t : INT; END_TYPE\n\nPut it before a POU that has no body: `{extern} FUNCTION log_value : BOOL VAR_INPUT v : INT; END_VAR END_FUNCTION`.";
    NESTED_COMMENT = "IL0038", "a comment inside a comment",
        "Comments do not nest: a comment ends at the first `*)`, even when a `(*` stands inside it, and the text after that `*)` is read as IL.\n\n    (* outer (* inner *) still comment? *)\n\nHere the comment ends after `inner`, and `still comment? *)` is not a comment. Remove the inner `(*` or its `*)`, or end the first comment before the inner one and open another after it.";
    MACRO_TOO_LARGE = "IL0035", "an `il!` input over 16 MiB",
        "One `il!` call takes at most 16 MiB of IL (inline, or all its files together): the macro runs inside rustc on every build of the crate, and its tokens stay in rustc's memory. Larger programs belong in build.rs, whose output is written once and rebuilt only when the IL changes.\n\n    il_macros::il!(file = \"plc/huge.il\");   // 40 MiB\n\nCompile it with `il_codegen::Builder` in build.rs and `include!` the result.";
    NOT_FORMATTED = "IL0049", "a file the formatter does not lay out",
        "`ilc fmt` (and the editor's formatting) changes only blanks and the case of keywords, and checks that the result has the same tokens as the file. It refuses a file it cannot lay out safely: one with syntax errors (they are shown instead), or one with text between tokens that is neither a blank, a comment nor a pragma. The file is left as it is.\n\n    $ ilc fmt motor.il\n    error[IL0049]: this file is not formatted: the layout would change its tokens (a formatter bug: please report it) here\n\nFix the syntax errors first. The message names anything else it refuses; please report a file that the formatter refuses without a syntax error.";
}
