//! What `ilc run` drives: one PROGRAM (or FUNCTION_BLOCK) instance, or a
//! whole CONFIGURATION with its tasks. The scan loop and the table in
//! `run.rs` are the same for both; only naming places and scanning differ.

use il_codegen::ir::types::Ty;
use il_interp::il_std::Cycle;
use il_interp::{ConfigMachine, ConfigPlace, Hook, HostPlace, Machine, Value};

/// A machine `ilc run` can scan.
pub trait Target {
    /// A resolved `--set`/`--watch` name.
    type Place;
    /// The top scope's name (the VCD's top module).
    fn top(&self) -> String;
    fn lookup(&self, text: &str) -> Result<Self::Place, String>;
    fn parse_for(&self, p: &Self::Place, text: &str) -> Result<Value, String>;
    fn set_at(&mut self, ctx: &mut Cycle, p: &Self::Place, v: Value) -> Result<(), String>;
    fn get_at(&self, ctx: &Cycle, p: &Self::Place) -> Value;
    /// The name as given and the place's type.
    fn describe<'a>(&self, p: &'a Self::Place) -> (&'a str, &'a Ty);
    /// The names watched when `--watch` is not given.
    fn watchable(&self) -> Vec<String>;
    /// One scan: the program once, or every task released now.
    fn scan(&mut self, ctx: &mut Cycle) -> Result<(), String>;
    /// Attach a debugger hook to every program it runs (`ilc debug`, `--flow`).
    fn set_hook(&mut self, hook: Option<Box<dyn Hook>>);
    /// The attached hook, if it is a `H`.
    fn hook_mut<H: Hook>(&mut self) -> Option<&mut H>;
    /// Detach the hook and have it back, if it is a `H`.
    fn take_hook<H: Hook>(&mut self) -> Option<Box<H>>;
}

impl Target for Machine {
    type Place = HostPlace;
    fn top(&self) -> String {
        self.pou().name.clone()
    }
    fn lookup(&self, text: &str) -> Result<HostPlace, String> {
        Machine::lookup(self, text)
    }
    fn parse_for(&self, p: &HostPlace, text: &str) -> Result<Value, String> {
        Machine::parse_for(self, p, text)
    }
    fn set_at(&mut self, ctx: &mut Cycle, p: &HostPlace, v: Value) -> Result<(), String> {
        Machine::set_at(self, ctx, p, v)
    }
    fn get_at(&self, ctx: &Cycle, p: &HostPlace) -> Value {
        Machine::get_at(self, ctx, p)
    }
    fn describe<'a>(&self, p: &'a HostPlace) -> (&'a str, &'a Ty) {
        (&p.text, &p.ty)
    }
    fn watchable(&self) -> Vec<String> {
        Machine::watchable(self)
    }
    fn scan(&mut self, ctx: &mut Cycle) -> Result<(), String> {
        Machine::scan(self, ctx).map(|_| ())
    }
    fn set_hook(&mut self, hook: Option<Box<dyn Hook>>) {
        Machine::set_hook(self, hook)
    }
    fn hook_mut<H: Hook>(&mut self) -> Option<&mut H> {
        Machine::hook_mut(self)
    }
    fn take_hook<H: Hook>(&mut self) -> Option<Box<H>> {
        Machine::take_hook(self)
    }
}

impl Target for ConfigMachine {
    type Place = ConfigPlace;
    fn top(&self) -> String {
        self.def().name.clone()
    }
    fn lookup(&self, text: &str) -> Result<ConfigPlace, String> {
        ConfigMachine::lookup(self, text)
    }
    fn parse_for(&self, p: &ConfigPlace, text: &str) -> Result<Value, String> {
        ConfigMachine::parse_for(self, p, text)
    }
    fn set_at(&mut self, ctx: &mut Cycle, p: &ConfigPlace, v: Value) -> Result<(), String> {
        ConfigMachine::set_at(self, ctx, p, v)
    }
    fn get_at(&self, ctx: &Cycle, p: &ConfigPlace) -> Value {
        ConfigMachine::get_at(self, ctx, p)
    }
    fn describe<'a>(&self, p: &'a ConfigPlace) -> (&'a str, &'a Ty) {
        (&p.text, &p.ty)
    }
    fn watchable(&self) -> Vec<String> {
        ConfigMachine::watchable(self)
    }
    fn scan(&mut self, ctx: &mut Cycle) -> Result<(), String> {
        self.run(ctx).map(|_| ())
    }
    fn set_hook(&mut self, hook: Option<Box<dyn Hook>>) {
        ConfigMachine::set_hook(self, hook)
    }
    fn hook_mut<H: Hook>(&mut self) -> Option<&mut H> {
        ConfigMachine::hook_mut(self)
    }
    fn take_hook<H: Hook>(&mut self) -> Option<Box<H>> {
        ConfigMachine::take_hook(self)
    }
}
