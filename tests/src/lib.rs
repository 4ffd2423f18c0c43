//! Generated code under test. Everything here is produced by il-codegen;
//! `deny(warnings)` proves that it compiles without warnings in a user's crate.
#![deny(warnings)]
#![forbid(unsafe_code)]

/// Our IL test programs (`tests/plc/*.il`) through build.rs.
pub mod via_build {
    include!(concat!(env!("OUT_DIR"), "/generated_index.rs"));
}

/// The same programs through `il!(file = ...)`.
pub mod via_macro {
    include!(concat!(env!("OUT_DIR"), "/macro_index.rs"));
}

/// Hostile names, comments and strings (`tests/plc-hostile/hostile.il`)
/// through build.rs, apart from the other programs: its POUs named like the
/// prelude (`Some`, `Option`, `Default`, `Result`) would shadow it in test
/// files that glob-import `via_build` or `via_macro`.
pub mod hostile_build {
    include!(concat!(env!("OUT_DIR"), "/hostile/hostile.rs"));
}

/// The same through `il!(file = ...)`.
pub mod hostile_macro {
    il_macros::il!(file = "plc-hostile/hostile.il");
}

/// The tank controller of the new-user test (`new-user/plc`): two files,
/// one program, through one `il!(files = [...])`.
pub mod tank_macro {
    il_macros::il!(files = ["new-user/plc/types.il", "new-user/plc/tank.il"]);
}

/// The Annex F programs of IEC 61131-3, from `../shared/corpus`.
#[cfg(il_corpus)]
pub mod annex_f {
    include!(concat!(
        env!("OUT_DIR"),
        "/annex_f/beremiz_matiec_cmd_monitor_il.rs"
    ));
    include!(concat!(
        env!("OUT_DIR"),
        "/annex_f/beremiz_matiec_stack_int_il.rs"
    ));
    include!(concat!(
        env!("OUT_DIR"),
        "/annex_f/beremiz_matiec_weigh_il.rs"
    ));
    include!(concat!(env!("OUT_DIR"), "/annex_f/fwd_rev_mon_fixed.rs"));
}

/// `CounterIL`, the IL POU of Beremiz's first_steps PLCopen XML project
/// (`../shared/corpus/beremiz_beremiz_first_steps_plc.xml`).
#[cfg(il_plcopen_corpus)]
pub mod first_steps {
    include!(concat!(
        env!("OUT_DIR"),
        "/plcopen/beremiz_beremiz_first_steps_plc.rs"
    ));
}
