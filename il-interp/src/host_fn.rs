//! Host functions (`{extern}` FUNCTIONs) in the interpreter. Generated code
//! calls the crate's Rust function; here the embedder registers a closure
//! of the same meaning. Without one, the call runs the declared interface
//! only: the result is its type's default and outputs keep their initial
//! values (what `ilc run` does, and says, for a program that calls one).
//!
//! A host FUNCTION_BLOCK or PROGRAM (`{extern}`, or a POU of a CODESYS
//! export whose body is not IL) is registered the same way: the closure
//! gets the instance's variables in declaration order, changes them, and
//! its result is ignored; without one, a call changes nothing.

use crate::values::Value;
use il_std::Cycle;
use std::sync::Arc;

/// A host function's implementation: `vars` holds the FUNCTION's variables
/// in declaration order (inputs set from the call, in-outs with the caller's
/// values, outputs at their initial values); it may change outputs and
/// in-outs, and returns the result.
pub type HostFn = dyn Fn(&mut Cycle, &mut [Value]) -> Value + Send + Sync;

/// The registered implementations, by FUNCTION name (case-insensitive).
#[derive(Clone, Default)]
pub(crate) struct HostFns(Vec<(String, Arc<HostFn>)>);

impl std::fmt::Debug for HostFns {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list()
            .entries(self.0.iter().map(|(n, _)| n))
            .finish()
    }
}

impl HostFns {
    pub(crate) fn set(&mut self, name: &str, f: Arc<HostFn>) {
        self.0.retain(|(n, _)| !n.eq_ignore_ascii_case(name));
        self.0.push((name.to_string(), f));
    }
    pub(crate) fn get(&self, name: &str) -> Option<&Arc<HostFn>> {
        self.0
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|(_, f)| f)
    }
}
