//! `visit` on generated code (through build.rs and `il!`): every variable
//! with its name, IEC type and value, into FB instances, STRUCTs and arrays.

use il_std::trace::{Value, Visitor};
use il_std::{Cycle, TIME};

/// Writes each call as a line: `edge.t.Q: BOOL = Bool(true)`.
#[derive(Default)]
struct Lines {
    path: Vec<String>,
    out: Vec<String>,
}

impl Lines {
    fn name(&self, n: &str) -> String {
        let mut p = self.path.clone();
        p.push(n.to_string());
        p.join(".")
    }
}

impl Visitor for Lines {
    fn enter(&mut self, name: &str) {
        self.path.push(name.to_string());
    }
    fn enter_elem(&mut self, name: &str, index: &[i64]) {
        self.path.push(format!("{name}{index:?}"));
    }
    fn leave(&mut self) {
        self.path.pop().expect("leave after enter");
    }
    fn var(&mut self, name: &str, ty: &str, value: Value<'_>) {
        let line = format!("{}: {ty} = {value:?}", self.name(name));
        self.out.push(line);
    }
    fn elem(&mut self, name: &str, index: &[i64], ty: &str, value: Value<'_>) {
        let line = format!("{}{index:?}: {ty} = {value:?}", self.name(name));
        self.out.push(line);
    }
}

macro_rules! trace_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Plant, Traced};

            fn lines(f: impl FnOnce(&mut Lines)) -> Vec<String> {
                let mut l = Lines::default();
                f(&mut l);
                assert!(l.path.is_empty(), "every enter is left");
                l.out
            }

            #[test]
            fn offers_every_variable_with_its_iec_type() {
                let mut ctx = Cycle::new();
                let mut t = Traced::default();
                t.call(&mut ctx);
                t.go = true;
                ctx.advance(TIME::from_ms(10));
                t.call(&mut ctx);
                let got = lines(|l| t.visit(l));
                let expect = [
                    "go: BOOL = Bool(true)",
                    "n: DINT = Int { value: 0, bits: 32 }",
                    "w: WORD = UInt { value: 61455, bits: 16 }",
                    "r: REAL = Real(0.5)",
                    "phase: TracePhase = Enum { value: 5, name: \"Run\" }",
                    "p.x: INT = Int { value: 1, bits: 16 }",
                    "p.lit: BOOL = Bool(true)",
                    "a[1]: SINT = Int { value: 0, bits: 8 }",
                    "a[2]: SINT = Int { value: 0, bits: 8 }",
                    "a[3]: SINT = Int { value: 7, bits: 8 }",
                    "m[0, 1]: UINT = UInt { value: 0, bits: 16 }",
                    "m[0, 2]: UINT = UInt { value: 0, bits: 16 }",
                    "m[1, 1]: UINT = UInt { value: 0, bits: 16 }",
                    "m[1, 2]: UINT = UInt { value: 9, bits: 16 }",
                    "name: STRING[8] = Str([97, 98, 99])",
                    "edge.go: BOOL = Bool(true)",
                    "edge.q: BOOL = Bool(false)",
                    "edge.t.IN: BOOL = Bool(true)",
                    "edge.t.PT: TIME = Time(20000000)",
                    "edge.t.Q: BOOL = Bool(false)",
                    "edge.t.ET: TIME = Time(0)",
                    "pulses[1].go: BOOL = Bool(false)",
                    "pulses[1].q: BOOL = Bool(false)",
                    "pulses[1].t.IN: BOOL = Bool(false)",
                    "pulses[1].t.PT: TIME = Time(20000000)",
                    "pulses[1].t.Q: BOOL = Bool(false)",
                    "pulses[1].t.ET: TIME = Time(0)",
                    "pulses[2].go: BOOL = Bool(true)",
                    "pulses[2].q: BOOL = Bool(false)",
                    "pulses[2].t.IN: BOOL = Bool(true)",
                    "pulses[2].t.PT: TIME = Time(20000000)",
                    "pulses[2].t.Q: BOOL = Bool(false)",
                    "pulses[2].t.ET: TIME = Time(0)",
                    "since: TIME = Time(0)",
                ];
                assert_eq!(got, expect);
                // Values follow the scans: the timer runs, the counter counts.
                for _ in 0..2 {
                    ctx.advance(TIME::from_ms(10));
                    t.call(&mut ctx);
                }
                let got = lines(|l| t.visit(l));
                assert!(
                    got.contains(&"edge.t.ET: TIME = Time(20000000)".to_string()),
                    "{got:#?}"
                );
                assert!(
                    got.contains(&"edge.q: BOOL = Bool(true)".to_string()),
                    "{got:#?}"
                );
                assert!(got.contains(&"n: DINT = Int { value: 2, bits: 32 }".to_string()));
            }

            #[test]
            fn a_configuration_offers_globals_and_programs() {
                let plant = Plant::default();
                let got = lines(|l| plant.visit(l));
                assert!(got.iter().any(|l| l.starts_with("ticks: DINT")), "{got:#?}");
                // Program instances are scopes, with their own variables.
                assert!(
                    got.iter()
                        .any(|l| l.ends_with("sum: DINT = Int { value: 0, bits: 32 }")
                            && l.contains('.')),
                    "{got:#?}"
                );
            }
        }
    };
}

trace_tests!(via_build);
trace_tests!(via_macro);
