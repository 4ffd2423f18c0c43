//! The debugger's hook: every statement seen with its frame, the call
//! stack with instance paths, the current result, evaluation, and the
//! machine's results unchanged by a hook.

use il_codegen::diag::SourceFile;
use il_interp::{Cr, Here, Hook, Machine, Value};

const SRC: &str = "\
FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
    LD   x
    MUL  2
    ST   Twice
END_FUNCTION
FUNCTION_BLOCK Counter
VAR_INPUT up : BOOL; END_VAR
VAR_OUTPUT n : INT; END_VAR
VAR edge : R_TRIG; END_VAR
    CAL  edge(CLK := up)
    LD   edge.Q
    JMPCN done
    LD   n
    Twice
    ST   n
done:
END_FUNCTION_BLOCK
PROGRAM Main
VAR pumps : ARRAY [1..2] OF Counter; go : BOOL := TRUE; q : INT; END_VAR
    CAL  pumps[2](up := go)
    LD   pumps[2].n
    ADD  1
    ST   q
END_PROGRAM
";

/// What the hook saw: per statement before it ran, the frames' paths, the line and the CR.
#[derive(Default)]
struct Rec {
    seen: Vec<(Vec<String>, u32, String)>,
    evals: Vec<String>,
}

impl Hook for Rec {
    fn before(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        let paths = at.frames().into_iter().map(|f| f.path).collect();
        let cr = match at.cr(0) {
            Some(Cr::Value(v, t)) => format!("{} {t}", v.display()),
            Some(Cr::Undefined(why)) => format!("undefined ({why})"),
            None => "?".into(),
        };
        if at.pou().name == "Twice" {
            // The caller's frame is readable from inside the function.
            let (v, _) = at.eval(1, "edge.Q").map_err(|e| e.to_string())?;
            let (x, t) = at.eval(0, "x")?;
            self.evals
                .push(format!("{} {} {t}", v.display(), x.display()));
        }
        self.seen.push((paths, at.line(), cr));
        Ok(())
    }
}

fn machine() -> Machine {
    let prog = il_interp::load(&SourceFile::new("h.il", SRC)).unwrap();
    Machine::new(&prog, "Main").unwrap()
}

#[test]
fn hook_sees_frames_paths_and_the_current_result() {
    let mut m = machine();
    m.set_hook(Some(Box::new(Rec::default())));
    let mut ctx = il_interp::il_std::Cycle::new();
    m.scan(&mut ctx).unwrap();
    let rec = m.hook_mut::<Rec>().unwrap();
    let at = |line: u32| {
        rec.seen
            .iter()
            .find(|(_, l, _)| *l == line)
            .unwrap_or_else(|| panic!("line {line} not seen: {:?}", rec.seen))
            .clone()
    };
    assert_eq!(at(21).0, ["Main"]);
    assert_eq!(at(11).0, ["Main.pumps[2]", "Main"]);
    assert_eq!(at(11).2, "undefined (no value loaded)");
    assert_eq!(at(12).2, "undefined (after CAL on line 11)");
    assert_eq!(at(3).0, ["Twice", "Main.pumps[2]", "Main"]);
    assert_eq!(at(4).2, "0 INT");
    assert_eq!(at(23).2, "0 INT");
    assert_eq!(rec.evals[0], "TRUE 0 INT");
    // The hook changes nothing: the result is the unhooked one.
    let mut plain = machine();
    plain.scan(&mut il_interp::il_std::Cycle::new()).unwrap();
    assert_eq!(m.get("q"), plain.get("q"));
    assert_eq!(
        m.get("q"),
        Some(il_interp::int(1, il_codegen::ir::types::Elem::INT))
    );
}

/// A hook can end a scan that never would (a JMP loop, without the step limit).
#[test]
fn hook_error_ends_an_endless_scan() {
    struct Stop(u32);
    impl Hook for Stop {
        fn before(&mut self, _: &mut Here<'_>) -> Result<(), String> {
            self.0 += 1;
            if self.0 > 1000 {
                Err("paused".into())
            } else {
                Ok(())
            }
        }
    }
    let src = "PROGRAM L\nVAR n : INT; END_VAR\nagain:\n    LD n\n    ADD 1\n    ST n\n    JMP again\nEND_PROGRAM\n";
    let prog = il_interp::load(&SourceFile::new("l.il", src)).unwrap();
    let mut m = Machine::new(&prog, "L").unwrap();
    m.set_hook(Some(Box::new(Stop(0))));
    let e = m.scan(&mut il_interp::il_std::Cycle::new()).unwrap_err();
    assert_eq!(e, "paused");
    assert!(matches!(m.get("n"), Some(Value::Int(n, _)) if n > 100));
}

/// After a statement, the hook sees the fault it recorded.
#[test]
fn hook_sees_faults_after_the_statement() {
    struct F(Vec<u32>);
    impl Hook for F {
        fn before(&mut self, _: &mut Here<'_>) -> Result<(), String> {
            Ok(())
        }
        fn after(&mut self, at: &mut Here<'_>) -> Result<(), String> {
            if at.fault().is_some() {
                self.0.push(at.line());
            }
            Ok(())
        }
    }
    let src =
        "PROGRAM D\nVAR n : INT; z : INT; END_VAR\n    LD 7\n    DIV z\n    ST n\nEND_PROGRAM\n";
    let prog = il_interp::load(&SourceFile::new("d.il", src)).unwrap();
    let mut m = Machine::new(&prog, "D").unwrap();
    m.set_hook(Some(Box::new(F(Vec::new()))));
    m.scan(&mut il_interp::il_std::Cycle::new()).unwrap();
    assert_eq!(m.hook_mut::<F>().unwrap().0, [4]);
}

/// `Here::set_in` on an outer frame: shown at once in that frame, written
/// to its variable when the call returns (the instance's own statements
/// see nothing of it); the instance being called is refused there.
#[test]
fn a_write_to_an_outer_frame_lands_when_the_call_returns() {
    #[derive(Default)]
    struct W(Vec<String>);
    impl Hook for W {
        fn before(&mut self, at: &mut Here<'_>) -> Result<(), String> {
            // Inside pumps[2], at its first statement: write Main's `q`.
            if at.depth() == 2 && at.line() == 11 {
                let v = at.set_in(1, "q", "40").map_err(|e| e.to_string())?;
                self.0.push(v.display());
                self.0.push(at.eval(1, "q")?.0.display());
                self.0.push(at.set_in(1, "pumps[2].n", "9").unwrap_err());
                self.0.push(at.set_in(1, "go", "TRUE")?.display());
            }
            if at.depth() == 1 && at.line() == 22 {
                // Back in Main: `q` is 40 before `LD pumps[2].n` runs.
                self.0.push(at.eval(0, "q")?.0.display());
            }
            Ok(())
        }
    }
    let mut m = machine();
    m.set_hook(Some(Box::new(W::default())));
    m.scan(&mut il_interp::il_std::Cycle::new()).unwrap();
    let w = m.take_hook::<W>().unwrap();
    assert_eq!(w.0[..2], ["40", "40"]);
    assert!(
        w.0[2].contains("Main.pumps[2]") && w.0[2].contains("that frame"),
        "{:?}",
        w.0
    );
    assert_eq!(w.0[3..], ["TRUE", "40"]);
    // The write was overwritten by the program's own `ST q` afterwards.
    assert_eq!(
        m.get("q"),
        Some(il_interp::int(1, il_codegen::ir::types::Elem::INT))
    );
}
