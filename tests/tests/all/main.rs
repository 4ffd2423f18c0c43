//! The integration tests of generated code, one binary with a module per
//! topic: programs from `../plc` compiled by this crate's build.rs and by
//! `il!`, the trybuild cases of `../ui` (one batch), the differential test
//! against the interpreter and the fuzz replay. One binary links the
//! generated code once instead of once per file.

mod addresses;
mod annex_f;
mod cfg_forms;
mod cfg_paths;
mod corners;
mod debugger;
mod dialect;
mod differential;
mod edge_cases;
mod edges_strings;
mod encodings;
mod exp;
mod fb_calls;
mod functions;
mod fuzz_replay;
mod globals_tasks;
mod host_functions;
mod hostile;
mod jumps;
mod labels_parens;
mod logiclab;
mod m221_blocks;
mod m221_project;
mod misc_lang;
mod motor;
mod new_user;
mod ops_arith;
mod ops_bool;
mod parens;
mod plcopen;
mod regressions;
mod retain;
mod rtc;
mod runtime_faults;
mod seeds;
mod std_blocks;
mod std_en_eno;
mod std_funcs;
mod subscript_exprs;
mod trace;
mod ui;
mod user_types;
