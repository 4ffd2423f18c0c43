//! Diagnostic codes of the strict standard (IL0300..IL0399): the
//! 3rd-edition forms that `--std=iec2003` refuses.

use crate::diag::codes::codes;

codes! {
    PRAGMA = "IL0301", "a pragma under the 2nd edition",
        "Pragmas `{ ... }` (TwinCAT's `{attribute 'qualified_only'}`, CODESYS's `{warning ...}`) are accepted and ignored by default. Checked against the 2nd edition (`--std=iec2003`, `Standard::Iec2003`, `il!(..., std = \"iec2003\")`) they are refused.\n\n    {attribute 'hide'}\n    PROGRAM Main\n\nRemove the pragma, or check with the default standard.";
    IMPLICIT_CONVERSION = "IL0302", "an implicit widening conversion under the 2nd edition",
        "By default a value meets a wider type without a conversion function (SINT into INT, INT into DINT or REAL, BYTE into WORD, REAL into LREAL, TIME into LTIME). Checked against the 2nd edition (`--std=iec2003`) every conversion is explicit.\n\n    LD  my_int\n    ST  my_dint    (* INT → DINT *)\n\nWrite `INT_TO_DINT` between them, or check with the default standard.";
    PARTIAL_ACCESS = "IL0303", "partial (bit) access under the 2nd edition",
        "By default `v.3`, `v.%X3`, `v.%B1`, `v.%W0`, `v.%D1` read and write one bit, byte, word or double word of a bit string or integer. Checked against the 2nd edition (`--std=iec2003`) they are refused.\n\n    LD  status.3\n\nMask and shift (`LD status / SHR 3 / AND 1`), or check with the default standard.";
    PARTLY_IN_INTERFACE = "IL0304", "a partly specified address in VAR_INPUT or VAR_OUTPUT under the 2nd edition",
        "By default a VAR_INPUT or VAR_OUTPUT of a PROGRAM or FUNCTION_BLOCK may be declared `AT %I*`, `%Q*` or `%M*`, as CODESYS-family tools allow, and a VAR_CONFIG gives it its address. The 2nd edition (2.4.1.1) allows partly specified addresses only in VAR; checked against it (`--std=iec2003`) the others are refused.\n\n    VAR_INPUT start AT %I* : BOOL; END_VAR\n\nDeclare the variable in VAR, or check with the default standard.";
}
