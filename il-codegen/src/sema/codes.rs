//! Diagnostic codes of the checker (IL0100..IL0199).

use crate::diag::codes::codes;

codes! {
    UNKNOWN_NAME = "IL0101", "unknown variable",
        "The operand names no variable of this POU.\n\n    LD  Strat   (* typo for Start *)\n\nDeclare it in a VAR block or fix the spelling; names are case-insensitive.";
    UNKNOWN_LABEL = "IL0102", "unknown label",
        "A jump names a label that does not exist in this POU.\n\n    JMPC  Done\n    ...\n    (* no line `Done:` *)";
    DUPLICATE_LABEL = "IL0103", "label defined twice",
        "Two lines carry the same label; a jump to it would be ambiguous.\n\n    L1: LD a\n    L1: LD b";
    DUPLICATE_DECL = "IL0104", "name declared twice",
        "Two variables, or two POUs, have the same (case-insensitive) name.\n\n    VAR x : INT; X : BOOL; END_VAR";
    UNKNOWN_TYPE = "IL0105", "unknown type",
        "A declaration names a type that is neither elementary, a standard function block, nor a FUNCTION_BLOCK of this file.\n\n    VAR t : TONN; END_VAR";
    TYPE_MISMATCH = "IL0106", "operand type does not match the current result",
        "IL operators need the current result and the operand to be of the same type (IEC 61131-3, Table 52, note 2).\n\n    LD  my_int\n    ADD my_real   (* INT + REAL: convert first with INT_TO_REAL *)";
    BAD_OPERATOR_TYPE = "IL0107", "operator not defined for this type",
        "The operator cannot work on this type: AND/OR/XOR/NOT need BOOL or a bit string, ADD..DIV numbers (or TIME), MOD integers.\n\n    LD  speed   (* INT *)\n    AND TRUE";
    CR_UNDEFINED = "IL0108", "the current result is undefined here",
        "The instruction uses the current result, but none is defined: at the start of a body, or after CAL of a function block (whose call leaves the CR undefined).\n\n    CAL timer\n    ST  done    (* load something first: LD timer.Q *)";
    CR_DISAGREES = "IL0109", "the current result has different types on the paths into a label",
        "A label is reached from several places with current results of different types; the CR is unusable after it until the next LD.\n\n    LD  flag      (* BOOL *)\n    JMPC L\n    LD  count     (* INT *)\n    L: ST x       (* BOOL or INT? *)";
    COND_NOT_BOOL = "IL0110", "conditional instruction needs a BOOL current result",
        "JMPC, CALC, RETC and their N forms test the current result, which must be BOOL.\n\n    LD   count\n    JMPC L      (* compare first: GT 0 *)";
    NOT_WRITABLE = "IL0111", "cannot store here",
        "The target of ST, S or R must be a writable variable: not a CONSTANT, not a literal, not an output of another function block.\n\n    VAR CONSTANT max : INT := 10; END_VAR\n    ST max";
    UNKNOWN_MEMBER = "IL0112", "no such input or output",
        "The function block has no input or output of that name.\n\n    LD FF.Q     (* an SR's output is Q1 *)";
    NOT_AN_FB = "IL0113", "not a function block instance",
        "CAL and the input operators (IN, PT, CU, ...) need an instance of a function block.\n\n    CAL  count   (* count is an INT *)";
    UNKNOWN_FUNCTION = "IL0114", "unknown function",
        "An unknown word in the operator field is taken as a function call, and no FUNCTION of that name exists (neither standard nor in this file). Vendor built-ins are not IEC 61131-3.\n\n    dbg 1\n\nCall a FUNCTION that exists, or, when the runtime provides it, declare it as a host function (`{extern}`, IL0140) and give its body in Rust.";
    ARG_COUNT = "IL0115", "wrong number of arguments",
        "The call passes more or fewer arguments than the function takes. In IL the current result is the first argument.\n\n    LD x\n    LIMIT 0     (* LIMIT(MN, IN, MX): CR is MN... write LIMIT 0, 100 *)";
    LITERAL_RANGE = "IL0116", "literal does not fit its type",
        "The literal's value is outside the range of the type it gets from its use.\n\n    LD 300\n    ST my_sint   (* SINT: -128..127 *)";
    RECURSION = "IL0117", "recursion",
        "IEC 61131-3 forbids a POU from calling itself, directly or through others, and a FUNCTION_BLOCK from containing an instance of itself.";
    IN_PARENS = "IL0118", "not allowed inside parentheses",
        "Inside a deferred parenthesis only expression operators are allowed: no labels, jumps, CAL or RET.";
    UNREACHABLE = "IL0119", "unreachable instruction",
        "The instruction follows an unconditional JMP or RET and no label leads to it, so it never runs.";
    UNUSED_LABEL = "IL0120", "unused label",
        "No jump goes to this label.";
    UNSUPPORTED = "IL0121", "not supported yet",
        "The construct is valid IEC 61131-3 but this version of the compiler cannot translate it yet.";
    CONST_DIV_ZERO = "IL0122", "division by zero in constants",
        "Both operands are literals and the divisor is zero.";
    BAD_INPUT_OP = "IL0124", "input operator does not fit the instance",
        "Table 54 input operators set one input of a standard FB: S1/R for SR, S/R1 for RS, CLK for R_TRIG/F_TRIG, CU/R/PV for CTU, CD/LD/PV for CTD, CU/CD/R/LD/PV for CTUD, IN/PT for TP/TON/TOF.\n\n    PT C10    (* C10 is a CTU: it has no PT *)";
    BAD_INDEX = "IL0125", "wrong array access",
        "Subscripts must be integers, one per dimension, and only arrays can be subscripted; a constant subscript must be within the bounds.";
    BAD_IDENT = "IL0126", "invalid identifier",
        "An IEC identifier is letters, digits and single underscores, with at least one letter or digit: it cannot be `_` alone, contain two underscores in a row or end with an underscore (the generated code reserves such names); `_x` and `x_1` are fine.";
    BAD_ADDRESS = "IL0128", "invalid direct address",
        "The address does not fit: a located variable's type must have the address's size (%IX: BOOL; %IB: BYTE/SINT/USINT; %IW: WORD/INT/UINT; %ID: DWORD/DINT/UDINT/REAL; %IL: LWORD/LINT/ULINT/LREAL), the address must lie inside the process image, and inputs (%I) are written by the host only. A partly specified address (`AT %I*`, `%Q*`, `%M*`) stands in the VAR, VAR_INPUT or VAR_OUTPUT of a PROGRAM or FUNCTION_BLOCK only, and its size letter, if any, must fit the type.\n\n    sensor AT %IX0.0 : INT;   (* an INT needs %IW *)";
    BAD_GLOBAL = "IL0129", "VAR_EXTERNAL without a matching VAR_GLOBAL",
        "A POU uses a global through VAR_EXTERNAL, and the configuration that runs it (or the POU that calls the function block) has no global of that name and type. Globals are declared with VAR_GLOBAL in a CONFIGURATION or RESOURCE; a FUNCTION_BLOCK that uses a global needs the same VAR_EXTERNAL in every POU that holds an instance of it (the generated code passes the global down).\n\n    PROGRAM Main\n    VAR_EXTERNAL speed : INT; END_VAR\n    ...\n    CONFIGURATION Plant\n    VAR_GLOBAL speed : REAL; END_VAR   (* INT expected *)";
    BAD_IN_OUT = "IL0130", "VAR_IN_OUT needs a variable",
        "A VAR_IN_OUT parameter is passed by reference: every call must bind it (`CAL inst(io := variable)`), to a variable of exactly its type, not to a literal or an expression. A PROGRAM's VAR_IN_OUT is bound where the configuration instantiates it (`PROGRAM p WITH t : P (io := g);`), to a writable global that is not in the process image, not also one of the program's VAR_EXTERNALs, and not bound to another of its VAR_IN_OUTs.\n\n    CAL  scaler(buffer := 5)   (* buffer is VAR_IN_OUT *)";
    BAD_CONFIG = "IL0131", "invalid configuration, task or program instance",
        "A CONFIGURATION/RESOURCE names an unknown task or program, a TASK has an invalid INTERVAL (a TIME literal or TIME global), PRIORITY or SINGLE (a BOOL global, a bit address or TRUE/FALSE), a program instance's arguments do not fit, or a VAR_CONFIG / VAR_ACCESS path names nothing, has another type, steps into something that has no members, has a subscript that is not a constant, or gives an address to a variable not declared `AT %I*`/`%Q*`/`%M*`. A VAR_ACCESS path may go through array elements and members (`Res.Prog.a[2]`, `Res.Prog.fbs[1].Q`, `g.field`); a VAR_CONFIG path names a whole variable of a program or FB instance (Ed.2 2.7.1), not an element or a member of a structure.\n\n    TASK fast (INTERVAL := 10, PRIORITY := 1);   (* INTERVAL needs a TIME: T#10ms *)";
    BAD_SECTION = "IL0132", "variable section not allowed here",
        "The VAR section cannot appear in this kind of POU, or cannot have that attribute: VAR_GLOBAL belongs in a CONFIGURATION or RESOURCE (POUs use globals through VAR_EXTERNAL); a FUNCTION has no VAR_EXTERNAL; VAR_EXTERNAL and VAR_IN_OUT take no initial value and no address.\n\n    FUNCTION_BLOCK Pump\n    VAR_GLOBAL pressure : REAL; END_VAR";
    TOO_DEEP = "IL0133", "types nested too deeply",
        "Function block instances, STRUCTs and arrays nest at most 120 levels deep: each FUNCTION_BLOCK, PROGRAM or STRUCT that holds the next is one level, each array dimension one (a standard FB counts as 3, a STRING as 2, other elementary types as 1). rustc cannot compile Rust types nested much deeper (its recursion limit is 128, and the generated code adds a few levels around a program).\n\n    FUNCTION_BLOCK L1  VAR next : L2; END_VAR  END_FUNCTION_BLOCK\n    FUNCTION_BLOCK L2  VAR next : L3; END_VAR  END_FUNCTION_BLOCK\n    (* ... up to L121 *)\n\nFlatten the hierarchy: hold the inner blocks side by side in one block.";
    TOO_LARGE = "IL0134", "array too large for the stack",
        "An array of more than 64 KiB is kept on the heap when it is a VAR, VAR_INPUT or VAR_OUTPUT of a FUNCTION_BLOCK or PROGRAM (creating the instance then never builds it on the stack). Anywhere else it would be a value on the stack, which is a few MiB for a whole thread, and is refused: in a FUNCTION or VAR_TEMP, as a VAR_IN_OUT, VAR_EXTERNAL or VAR_GLOBAL, as a STRUCT field, as rows of more than 64 KiB (only the first dimension goes to the heap), and loaded, stored or passed as a whole.\n\n    PROGRAM Main\n    VAR samples, copy : ARRAY[0..99999] OF LREAL; END_VAR\n        LD   samples     (* 800000 bytes through the CR: copy element by element *)\n        ST   copy\n    END_PROGRAM";
    BAD_PART = "IL0135", "partial access out of range or on the wrong type",
        "Partial access (3rd edition) reads or writes one bit (`v.3`, `v.%X3`), byte (`v.%B1`), word (`v.%W1`) or double word (`v.%D1`) of a bit string or integer variable; the part must lie inside the variable.\n\n    VAR status : WORD; END_VAR\n    LD status.16    (* a WORD has bits 0..15 *)\n\nUse a bit number below the width, or a wider variable.";
    HOST_BODY = "IL0140", "a host FUNCTION with a body or local variables",
        "A FUNCTION marked `{extern}` is a host function: IL declares its interface (result, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT) and the crate around the generated code provides its body as a Rust function of the same name. It has no instructions and no VAR or VAR_TEMP of its own.\n\n    {extern}\n    FUNCTION log_value : BOOL\n    VAR_INPUT v : INT; END_VAR\n        LD v\n    END_FUNCTION\n\nRemove the instructions (write them in Rust: `fn log_value(ctx: &mut il_std::Cycle, v: i16) -> bool`), or remove `{extern}` to compile the FUNCTION from IL.";
    BAD_INIT = "IL0127", "invalid initial value",
        "The initial value does not fit the declared type, or the type itself is wrong where it is declared: a subrange is of an integer type (SINT .. ULINT, not a bit string such as WORD), its limits are integer literals inside that type, and the lower one is not above the upper one. Every TYPE and variable is checked where it is declared, whether anything uses it or not.\n\n    TYPE Level : SINT (0..300); END_TYPE   (* a SINT holds -128..127 *)";
}
