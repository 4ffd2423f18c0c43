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
//! assert_eq!(m.get("n"), Some(Value::Int(2, il_codegen::ir::types::Elem::INT)));
//! ```

mod calls;
mod config;
mod config_host;
mod constants;
mod debug;
mod expressions;
mod flow;
mod host;
mod host_fn;
mod places;
mod stdfn;
mod values;

pub use config::ConfigMachine;
pub use config_host::ConfigPlace;
pub use constants::parse_literal;
pub use debug::{Cr, FrameInfo, Here, Hook, Shown, Undefined, type_of_value};
pub use host::HostPlace;
pub use host_fn::HostFn;
/// The runtime the interpreter runs on (for front ends without their own dependency).
pub use il_std;
pub use values::StdFb;
pub use values::{Instance, Struct, Value, fmt_dur};

use il_codegen::diag::SourceFile;
use il_codegen::ir::PouKind;
use il_codegen::ir::types::{Elem, Ty};
use il_codegen::ir::{CheckedPou, Program};
use il_std::Cycle;
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

/// The host FUNCTIONs (`{extern}`) of `prog`.
fn host_functions(prog: &Program) -> Vec<&str> {
    prog.pous
        .iter()
        .filter(|p| p.host)
        .map(|p| p.name.as_str())
        .collect()
}

fn host_function(
    prog: &Program,
    hosts: &mut host_fn::HostFns,
    name: &str,
    f: std::sync::Arc<HostFn>,
) -> Result<(), String> {
    let names = host_functions(prog);
    match names.iter().find(|n| n.eq_ignore_ascii_case(name)) {
        Some(n) => {
            hosts.set(n, f);
            Ok(())
        }
        None => Err(format!(
            "no host FUNCTION named `{name}` (`{{extern}}` FUNCTIONs: {})",
            if names.is_empty() {
                "none".to_string()
            } else {
                names.join(", ")
            }
        )),
    }
}

/// A program (or function block) instance ready to scan.
#[derive(Clone, Debug)]
pub struct Machine {
    prog: std::sync::Arc<Program>,
    /// POU names as `&'static str` for `Cycle::fault` (leaked once per machine).
    names: Vec<&'static str>,
    inst: Instance,
    steps: u64,
    /// The error of this scan already says where it comes from.
    error_located: bool,
    /// Implementations of the program's host FUNCTIONs.
    hosts: host_fn::HostFns,
    /// The debugger attached, if any ([`Machine::set_hook`]).
    dbg: debug::Dbg,
    /// Where an error's statement is in the user's files ([`Machine::set_locate`]).
    locate: Places,
}

/// Places a statement in the file the user wrote: (POU, IL line, IL
/// column) → `file:line:col`. A program read from a PLCopen XML project or
/// a CODESYS export runs IL its import made; its errors point into the
/// XML or the export (the pipeline's span maps), not into that IL.
pub type Locate = std::sync::Arc<dyn Fn(&str, u32, u32) -> String + Send + Sync>;

#[derive(Clone, Default)]
struct Places(Option<Locate>);

impl std::fmt::Debug for Places {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "mapped"
        } else {
            "IL lines"
        })
    }
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

// What an instance holds between calls (the IR's rule for paths too).
use il_codegen::ir::path::held;

impl Machine {
    /// An instance of the PROGRAM or FUNCTION_BLOCK `name` (case-insensitive)
    /// with its declared initial values.
    pub fn new(prog: &Program, name: &str) -> Result<Machine, String> {
        let mut m = Machine::bare(prog);
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

    /// A machine without an instance yet (a configuration holds its own).
    pub(crate) fn bare(prog: &Program) -> Machine {
        let names = prog
            .pous
            .iter()
            .map(|p| &*Box::leak(p.name.clone().into_boxed_str()))
            .collect();
        Machine {
            prog: std::sync::Arc::new(prog.clone()),
            names,
            inst: Instance {
                pou: 0,
                vars: Vec::new(),
                edge_mem: Vec::new(),
            },
            steps: 0,
            error_located: false,
            hosts: Default::default(),
            dbg: Default::default(),
            locate: Places::default(),
        }
    }

    /// Name the place of an error's statement with `f` instead of the
    /// program's file and its IL line and column.
    pub fn set_locate(&mut self, f: Locate) {
        self.locate = Places(Some(f));
    }

    /// Run `f` for each call of the host FUNCTION `name` (an `{extern}`
    /// FUNCTION: the generated code calls the crate's Rust function of that
    /// name, the interpreter this closure). Without one, a call returns the
    /// result type's default and leaves the outputs at their initial values.
    /// A host FUNCTION_BLOCK or PROGRAM (`{extern}`, or a CODESYS POU whose
    /// body is not IL) is registered the same way: `f` gets the instance's
    /// variables in declaration order and its result is ignored.
    pub fn host_function(
        &mut self,
        name: &str,
        f: impl Fn(&mut Cycle, &mut [Value]) -> Value + Send + Sync + 'static,
    ) -> Result<(), String> {
        host_function(&self.prog, &mut self.hosts, name, std::sync::Arc::new(f))
    }

    /// The host FUNCTIONs of the program (`{extern}`), by name.
    pub fn host_functions(&self) -> Vec<&str> {
        host_functions(&self.prog)
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

    /// Read a variable of the instance, or a part of one (`t1.Q`,
    /// `tank.level`, `arr[2].x`); `None` for an unknown name and for the
    /// process image (located variables, addresses: [`Machine::get_at`]).
    pub fn get(&self, name: &str) -> Option<Value> {
        let p = self.lookup(name).ok()?;
        if p.location().is_some() {
            return None;
        }
        // The process image is not read: any cycle will do.
        Some(self.get_at(&Cycle::new(), &p))
    }

    /// The declared type of a variable, a part of one, or a direct address.
    pub fn type_of(&self, name: &str) -> Option<Ty> {
        self.lookup(name).ok().map(|p| p.ty)
    }

    /// Write a variable of the instance or a part of one; the value must have
    /// its type. Located variables and addresses: [`Machine::set_at`].
    pub fn set(&mut self, name: &str, v: Value) -> Result<(), String> {
        let p = self.lookup(name)?;
        if let Some(l) = p.location() {
            return Err(format!(
                "`{name}` is in the process image ({}): set it with `set_at` and the cycle",
                l.text
            ));
        }
        self.set_at(&mut Cycle::new(), &p, v)
    }

    /// Parse `text` as a value of the type of variable `name` (IEC literal
    /// forms: `TRUE`, `42`, `-1.5`, `T#10ms`, `16#FF`, `'text'`, `Color#Red`).
    pub fn parse_value(&self, name: &str, text: &str) -> Result<Value, String> {
        let p = self.lookup(name)?;
        self.parse_for(&p, text)
    }

    /// One scan (one call of the instance).
    pub fn scan(&mut self, ctx: &mut Cycle) -> Result<(), String> {
        self.steps = 0;
        self.error_located = false;
        let mut inst = std::mem::take(&mut self.inst);
        if self.dbg.on() {
            self.dbg_enter(self.prog.pous[inst.pou].name.clone());
        }
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
        self.error_located = false;
        let (r, outs, _) = self.call_function(p, args, Vec::new(), ctx)?;
        Ok((r, outs))
    }
}

/// Wrapping of an integer into a type, for callers building values by hand.
pub fn int(v: i128, e: Elem) -> Value {
    Value::Int(wrap(v, e), e)
}
