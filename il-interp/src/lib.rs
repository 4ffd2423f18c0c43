//! The reference interpreter: runs the checked program (after semantic
//! analysis, before emission) directly, following docs/semantics.md and giving
//! the same results as the generated Rust: wrapping integers, DIV/MOD by zero
//! → 0 with a `DivisionByZero` fault, index out of range → default value with
//! an `IndexOutOfRange` fault, the real il-std blocks, R_EDGE/F_EDGE memory,
//! FUNCTION outputs as out-parameters, EN/ENO.
//!
//! ```
//! use il_codegen::diag::SourceFile;
//! use il_interp::{Machine, Value};
//! let src = "PROGRAM P\nVAR n : INT; END_VAR\nLD n\nADD 1\nST n\nEND_PROGRAM\n";
//! let prog = il_interp::load(&SourceFile::new("p.il", src)).unwrap();
//! let mut m = Machine::new(&prog, "P").unwrap();
//! let mut ctx = il_std::Cycle::new();
//! m.scan(&mut ctx).unwrap();
//! m.scan(&mut ctx).unwrap();
//! assert_eq!(m.get("n"), Some(Value::Int(2, il_codegen::sema::types::Elem::INT)));
//! ```

mod calls;
mod constants;
mod expressions;
mod flow;
mod places;
mod stdfn;
mod values;

pub use constants::parse_literal;
/// The runtime the interpreter runs on (for front ends without their own dependency).
pub use il_std;
pub use values::StdFb;
pub use values::{Instance, Value, fmt_dur};

use il_codegen::ast::PouKind;
use il_codegen::diag::SourceFile;
use il_codegen::sema::ir::{CheckedPou, Program, Storage, Var};
use il_codegen::sema::types::{Elem, Ty};
use il_std::Cycle;
use places::Step;
use values::wrap;

/// Instructions one scan may execute before the interpreter gives up (an
/// endless IL loop would hang the PLC too; here it is an error).
pub const STEP_LIMIT: u64 = 50_000_000;

/// Parse and check one source file through the compiler's pipeline (the
/// same rules as `il!`, build.rs and `ilc`); the error is the rendered
/// diagnostics.
pub fn load(file: &SourceFile) -> Result<Program, String> {
    load_std(file, il_codegen::Standard::default())
}

/// [`load`] against a standard (`ilc run --std=iec2003`).
pub fn load_std(file: &SourceFile, standard: il_codegen::Standard) -> Result<Program, String> {
    let diags = match il_codegen::Program::new()
        .standard(standard)
        .il(file.clone())
        .check()
        .into_ir()
    {
        Ok(mut ir) => return Ok(ir.remove(0)),
        Err(mut d) => d.remove(0),
    };
    let msgs: Vec<String> = diags
        .iter()
        .filter(|d| d.is_error())
        .map(|d| il_codegen::diag::render::render_short(file, d))
        .collect();
    Err(msgs.join("\n"))
}

/// A program (or function block) instance ready to scan.
#[derive(Clone, Debug)]
pub struct Machine {
    prog: std::sync::Arc<Program>,
    /// POU names as `&'static str` for `Cycle::fault` (leaked once per machine).
    names: Vec<&'static str>,
    inst: Instance,
    steps: u64,
}

/// The state of one call of a POU: its variables, current results and saves.
pub(crate) struct Frame {
    pou: usize,
    vars: Vec<Value>,
    /// The edge seen in this call, for R_EDGE/F_EDGE inputs.
    edges: Vec<Option<bool>>,
    cr: Vec<Value>,
    saves: Vec<Value>,
    ret: Value,
}

fn find_var(pou: &CheckedPou, name: &str) -> Option<usize> {
    pou.vars.iter().position(|v| v.name == name).or_else(|| {
        pou.vars
            .iter()
            .position(|v| v.name.eq_ignore_ascii_case(name))
    })
}

/// Whether the instance holds `v` between calls: its memory
/// ([`Storage::Instance`]) and, unlike generated code, its VAR_EXTERNALs
/// ([`Storage::External`] says why).
fn held(v: &Var) -> bool {
    matches!(v.storage, Storage::Instance | Storage::External)
}

impl Machine {
    /// An instance of the PROGRAM or FUNCTION_BLOCK `name` (case-insensitive)
    /// with its declared initial values.
    pub fn new(prog: &Program, name: &str) -> Result<Machine, String> {
        let names = prog
            .pous
            .iter()
            .map(|p| &*Box::leak(p.name.clone().into_boxed_str()))
            .collect();
        let mut m = Machine {
            prog: std::sync::Arc::new(prog.clone()),
            names,
            inst: Instance {
                pou: 0,
                vars: Vec::new(),
                edge_mem: Vec::new(),
            },
            steps: 0,
        };
        let Some(pou) = m
            .prog
            .pous
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name) && p.kind != PouKind::Function)
        else {
            let avail: Vec<&str> = m
                .prog
                .pous
                .iter()
                .filter(|p| p.kind != PouKind::Function)
                .map(|p| p.name.as_str())
                .collect();
            return Err(format!(
                "no PROGRAM or FUNCTION_BLOCK named `{name}` (there is {})",
                if avail.is_empty() {
                    "none".to_string()
                } else {
                    avail.join(", ")
                }
            ));
        };
        m.inst = m.new_instance(pou)?;
        Ok(m)
    }

    /// The POU this machine runs.
    pub fn pou(&self) -> &CheckedPou {
        &self.prog.pous[self.inst.pou]
    }

    /// Names of the instance's variables (not temporaries), as declared.
    pub fn var_names(&self) -> Vec<String> {
        let pou = self.pou();
        (0..pou.vars.len())
            .filter(|&i| held(&pou.vars[i]))
            .map(|i| pou.vars[i].name.clone())
            .collect()
    }

    /// Every variable of the instance with its value, in declaration order.
    pub fn vars(&self) -> Vec<(String, Value)> {
        let pou = self.pou();
        (0..pou.vars.len())
            .filter(|&i| held(&pou.vars[i]))
            .map(|i| (pou.vars[i].name.clone(), self.inst.vars[i].clone()))
            .collect()
    }

    /// Read a variable, or a member with a dotted path (`t1.Q`, `sub.x`).
    pub fn get(&self, name: &str) -> Option<Value> {
        let mut parts = name.split('.');
        let pou = self.pou();
        let i = find_var(pou, parts.next()?)?;
        if !held(&pou.vars[i]) {
            return None;
        }
        let mut v = self.inst.vars[i].clone();
        for f in parts {
            v = self.field(&v, f)?;
        }
        Some(v)
    }

    /// The declared type of a variable or dotted member.
    pub fn type_of(&self, name: &str) -> Option<Ty> {
        let mut parts = name.split('.');
        let mut pou = self.pou();
        let i = find_var(pou, parts.next()?)?;
        let mut ty = pou.vars[i].ty.clone();
        for f in parts {
            let Ty::Fb(fb) = &ty else { return None };
            if let Some(p) = self
                .prog
                .pous
                .iter()
                .find(|p| p.name.eq_ignore_ascii_case(fb))
            {
                pou = p;
                ty = pou.vars[find_var(pou, f)?].ty.clone();
            } else {
                let s = il_std::signature::lookup_fb(fb)?;
                let p = s
                    .inputs
                    .iter()
                    .chain(s.outputs)
                    .find(|p| p.name.eq_ignore_ascii_case(f))?;
                ty = Ty::Elem(Elem::from_name(p.ty.name())?);
            }
        }
        Some(ty)
    }

    /// Write a variable or dotted member; the value must have its type.
    pub fn set(&mut self, name: &str, v: Value) -> Result<(), String> {
        let ty = self
            .type_of(name)
            .ok_or_else(|| format!("no variable `{name}` in {}", self.pou().name))?;
        let want = self.default_of(&ty)?;
        if std::mem::discriminant(&want) != std::mem::discriminant(&v)
            || matches!((&want, &v), (Value::Int(_, a), Value::Int(_, b)) if a != b)
            || matches!((&want, &v), (Value::Time(_, a), Value::Time(_, b)) if a != b)
        {
            return Err(format!("`{name}` is {ty}, not {}", v.display()));
        }
        let mut parts: Vec<&str> = name.split('.').collect();
        let first = parts.remove(0);
        let i = find_var(self.pou(), first).ok_or_else(|| format!("no variable `{name}`"))?;
        let steps: Vec<Step> = parts.iter().map(|f| Step::Field(f.to_string())).collect();
        let mut root = std::mem::replace(&mut self.inst.vars[i], Value::Bool(false));
        let ok = self.write_at(&mut root, &steps, v);
        self.inst.vars[i] = root;
        if ok {
            Ok(())
        } else {
            Err(format!("cannot write `{name}`"))
        }
    }

    /// Parse `text` as a value of the type of variable `name` (IEC literal
    /// forms: `TRUE`, `42`, `-1.5`, `T#10ms`, `16#FF`, `'text'`).
    pub fn parse_value(&self, name: &str, text: &str) -> Result<Value, String> {
        let ty = self
            .type_of(name)
            .ok_or_else(|| format!("no variable `{name}` in {}", self.pou().name))?;
        parse_literal(&ty, text).ok_or_else(|| format!("`{text}` is not a valid {ty} value"))
    }

    /// One scan (one call of the instance).
    pub fn scan(&mut self, ctx: &mut Cycle) -> Result<(), String> {
        self.steps = 0;
        let mut inst = std::mem::replace(
            &mut self.inst,
            Instance {
                pou: 0,
                vars: Vec::new(),
                edge_mem: Vec::new(),
            },
        );
        let r = self.call_instance(&mut inst, ctx);
        self.inst = inst;
        r
    }

    /// Call the user FUNCTION `name` with its inputs in declaration order:
    /// its result and its outputs in declaration order.
    pub fn call_function_named(
        &mut self,
        name: &str,
        args: Vec<Value>,
        ctx: &mut Cycle,
    ) -> Result<(Value, Vec<Value>), String> {
        let p = self
            .prog
            .pous
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name) && p.kind == PouKind::Function)
            .ok_or_else(|| format!("no FUNCTION named `{name}`"))?;
        self.steps = 0;
        let (r, outs, _) = self.call_function(p, args, Vec::new(), ctx)?;
        Ok((r, outs))
    }
}

/// Wrapping of an integer into a type, for callers building values by hand.
pub fn int(v: i128, e: Elem) -> Value {
    Value::Int(wrap(v, e), e)
}
