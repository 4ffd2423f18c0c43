//! il-runtime's tests: a real runtime, a real Modbus client over 127.0.0.1,
//! real retain files and a process killed with SIGKILL.

mod common;
mod modbus;
mod retain;
mod sched;
