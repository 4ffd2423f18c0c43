//! Strings and dates in `Main`: STRING variables (one `STRING[8]`, which
//! cuts and records a StringOverflow fault) through every string function
//! and the comparisons, and DATE, TIME_OF_DAY and DATE_AND_TIME through
//! their arithmetic functions, conversions and comparisons. Their inputs vary
//! per scan through the INT and TIME variables they take and through SEL on
//! the BOOL inputs.

use super::*;

/// The declarations in Main's VAR block.
pub(super) fn decls(strings: bool, dates: bool) -> String {
    let mut s = String::new();
    if strings {
        s.push_str(
            "    str0 : STRING;\n    str1 : STRING := 'ab';\n    str2 : STRING;\n    str8 : STRING[8];\n    n0 : INT;\n",
        );
    }
    if dates {
        s.push_str(
            "    dd : DATE := D#2024-02-29;\n    tdd : TOD := TOD#23:59:59.5;\n    \
             dtt : DT := DT#1999-12-31-23:59:59;\n    tmd : TIME;\n    nd : DINT;\n",
        );
    }
    s
}

/// The plain variables the typed generator may use too.
pub(super) fn vars(strings: bool, dates: bool) -> Vec<Var> {
    let mut v = Vec::new();
    if strings {
        v.push(Var {
            name: "n0".into(),
            ty: T::Int,
        });
    }
    if dates {
        v.push(Var {
            name: "tmd".into(),
            ty: T::Time,
        });
        v.push(Var {
            name: "nd".into(),
            ty: T::Dint,
        });
    }
    v
}

const STR_LITS: &[&str] = &[
    "''", "'a'", "'abc'", "'Hello'", "'x$'y'", "'a$Nb'", "'$41$42'", "'zz9'", "'ab'", "'bca'",
];
const STRS: &[&str] = &["str0", "str1", "str2"];

impl Pou<'_> {
    fn str_operand(&mut self) -> String {
        if self.rng.chance(40) {
            self.rng.pick(STR_LITS).to_string()
        } else {
            self.rng.pick(STRS).to_string()
        }
    }

    /// A length or position: small literals (negative and past the end too)
    /// or an INT variable (inputs hold any INT).
    fn str_int(&mut self) -> String {
        let ints = self.vars_of(T::Int);
        if !ints.is_empty() && self.rng.chance(35) {
            return self.rng.pick(&ints).clone();
        }
        self.rng
            .pick(&["0", "1", "2", "3", "5", "90", "INT#-1"])
            .to_string()
    }

    pub(super) fn string_block(&mut self) {
        let a = self.rng.pick(STRS).to_string();
        let dst = self.rng.pick(STRS).to_string();
        let op = *self.rng.pick(&[
            "CONCAT", "LEFT", "RIGHT", "MID", "INSERT", "DELETE", "REPLACE", "FIND", "LEN", "CMP",
            "SEL", "S8",
        ]);
        match op {
            "CMP" => {
                self.emit(format!("LD {a}"));
                let c = *self.rng.pick(&["EQ", "NE", "LT", "GT", "LE", "GE"]);
                let b = self.str_operand();
                self.emit(format!("{c} {b}"));
                self.finish_expr(T::Bool);
                self.mark("STRING comparison");
                return;
            }
            "SEL" => {
                self.bool_cond();
                let (x, y) = (self.rng.pick(STRS).to_string(), self.str_operand());
                self.emit(format!("SEL {x}, {y}"));
                self.emit(format!("ST {dst}"));
                self.mark("SEL of strings");
                return;
            }
            "S8" => {
                // STRING[8]: longer results are cut (and a fault recorded).
                self.emit("LD str8");
                if self.rng.chance(60) {
                    let l = *self.rng.pick(&["'xyz'", "'abcde'", "''"]);
                    self.emit(format!("CONCAT {l}"));
                    self.mark("CONCAT");
                } else {
                    let n = self.str_int();
                    self.emit(format!("RIGHT {n}"));
                    self.mark("RIGHT");
                }
                self.emit("ST str8");
                self.emit("LD str8");
                self.emit("LEN");
                self.emit("ST n0");
                self.mark("STRING[8] (cut, fault)");
                return;
            }
            _ => {}
        }
        self.emit(format!("LD {a}"));
        match op {
            "CONCAT" => {
                let b = self.str_operand();
                if self.rng.chance(25) {
                    let c = self.str_operand();
                    self.emit(format!("CONCAT {b}, {c}"));
                } else {
                    self.emit(format!("CONCAT {b}"));
                }
                self.mark("CONCAT");
            }
            "LEFT" | "RIGHT" => {
                let n = self.str_int();
                self.emit(format!("{op} {n}"));
                self.mark(if op == "LEFT" { "LEFT" } else { "RIGHT" });
            }
            "MID" | "DELETE" => {
                let (l, p) = (self.str_int(), self.str_int());
                self.emit(format!("{op} {l}, {p}"));
                self.mark(if op == "MID" { "MID" } else { "DELETE" });
            }
            "INSERT" => {
                let (b, p) = (self.str_operand(), self.str_int());
                self.emit(format!("INSERT {b}, {p}"));
                self.mark("INSERT");
            }
            "REPLACE" => {
                let (b, l, p) = (self.str_operand(), self.str_int(), self.str_int());
                self.emit(format!("REPLACE {b}, {l}, {p}"));
                self.mark("REPLACE");
            }
            "FIND" | "LEN" => {
                if op == "FIND" {
                    let b = self.str_operand();
                    self.emit(format!("FIND {b}"));
                    self.mark("FIND");
                } else {
                    self.emit("LEN");
                    self.mark("LEN");
                }
                self.emit("ST n0");
                return;
            }
            _ => unreachable!(),
        }
        self.emit(format!("ST {dst}"));
    }

    fn time_operand(&mut self) -> String {
        let vars = self.vars_of(T::Time);
        if !vars.is_empty() && self.rng.chance(50) {
            return self.rng.pick(&vars).clone();
        }
        self.rng
            .pick(&["T#1500ms", "T#1h", "T#-5s", "T#23h59m", "T#1d", "T#0s"])
            .to_string()
    }

    pub(super) fn date_block(&mut self) {
        match self.rng.below(9) {
            0 => {
                self.emit("LD dd");
                let t = *self.rng.pick(&["tdd", "TOD#00:00:01", "TOD#12:30:00.25"]);
                self.emit(format!("CONCAT_DATE_TOD {t}"));
                self.emit("ST dtt");
                self.mark("DATE/TOD/DT arithmetic");
            }
            1 | 2 => {
                let (v, f) = *self.rng.pick(&[
                    ("tdd", "ADD_TOD_TIME"),
                    ("tdd", "SUB_TOD_TIME"),
                    ("dtt", "ADD_DT_TIME"),
                    ("dtt", "SUB_DT_TIME"),
                ]);
                let t = self.time_operand();
                self.emit(format!("LD {v}"));
                self.emit(format!("{f} {t}"));
                self.emit(format!("ST {v}"));
                self.mark("DATE/TOD/DT arithmetic");
            }
            3 => {
                self.emit("LD dtt");
                if self.rng.chance(50) {
                    self.emit("DT_TO_DATE");
                    self.emit("ST dd");
                } else {
                    self.emit("DT_TO_TOD");
                    self.emit("ST tdd");
                }
                self.mark("DT_TO_DATE/DT_TO_TOD");
            }
            4 => {
                let (v, f, o) = *self.rng.pick(&[
                    ("dd", "SUB_DATE_DATE", "D#2020-01-01"),
                    ("tdd", "SUB_TOD_TOD", "TOD#01:00:00"),
                    ("dtt", "SUB_DT_DT", "DT#2000-01-01-00:00:00"),
                ]);
                self.emit(format!("LD {v}"));
                self.emit(format!("{f} {o}"));
                self.emit("ST tmd");
                self.mark("DATE/TOD/DT arithmetic");
            }
            5 => {
                let (v, o) = *self.rng.pick(&[
                    ("dd", "D#2024-03-01"),
                    ("tdd", "TOD#12:00:00"),
                    ("dtt", "DT#2000-01-01-00:00:00"),
                ]);
                let c = *self.rng.pick(&["EQ", "NE", "LT", "GT", "LE", "GE"]);
                self.emit(format!("LD {v}"));
                self.emit(format!("{c} {o}"));
                self.finish_expr(T::Bool);
                self.mark("DATE/TOD/DT comparison");
            }
            6 => {
                let (v, a, b) = *self.rng.pick(&[
                    ("dd", "D#2024-01-01", "D#2024-12-31"),
                    ("tdd", "TOD#06:00:00", "TOD#18:00:00"),
                ]);
                self.emit(format!("LD {v}"));
                if self.rng.chance(50) {
                    self.emit(format!("LIMIT {a}, {b}"));
                } else {
                    let m = *self.rng.pick(&["MAX", "MIN"]);
                    self.emit(format!("{m} {a}"));
                }
                self.emit(format!("ST {v}"));
                self.mark("LIMIT/MAX/MIN");
            }
            7 => {
                // TIME and integers
                if self.rng.chance(50) {
                    self.emit("LD tmd");
                    if self.rng.chance(50) {
                        self.emit("TIME_TO_DINT");
                    } else {
                        self.emit("TIME_TO_LINT");
                        self.emit("LINT_TO_DINT");
                    }
                    self.emit("ST nd");
                } else {
                    self.emit("LD nd");
                    self.emit("DINT_TO_TIME");
                    self.emit("ST tmd");
                }
                self.mark("TIME conversion");
            }
            _ => {
                self.emit("LD tmd");
                let t = self.time_operand();
                let op = *self.rng.pick(&["ADD", "SUB"]);
                self.emit(format!("{op} {t}"));
                let k = *self.rng.pick(&["MUL 3", "DIV 2", "DIV nd", "MUL nd"]);
                self.emit(k);
                self.emit("ST tmd");
                self.mark("TIME arithmetic");
            }
        }
    }
}
