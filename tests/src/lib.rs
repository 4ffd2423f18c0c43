//! Generated code under test. Everything here is produced by il-codegen;
//! `deny(warnings)` proves that it compiles without warnings in a user's crate,
//! even one that asks for documentation and clippy's pedantic lints (the
//! generated items document themselves or allow the pedantic lints on
//! themselves only; CI's `cargo clippy -- -D warnings` checks the latter).
#![deny(warnings)]
#![warn(missing_docs, clippy::pedantic)]
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

/// The Rust bodies of the host functions of `plc-host/host.il` (`{extern}`
/// FUNCTIONs): the generated code calls them like its own FUNCTIONs.
pub mod host_impl {
    use il_std::Cycle;

    /// `raw` limited to `lo..=hi`; `clipped` says whether it was.
    pub fn clamp_sensor(_ctx: &mut Cycle, raw: i16, lo: i16, hi: i16, clipped: &mut bool) -> i16 {
        let v = raw.clamp(lo, hi.max(lo));
        *clipped = v != raw;
        v
    }

    /// Counts its calls in the caller's variable.
    pub fn bump(_ctx: &mut Cycle, counter: &mut i32) -> bool {
        *counter = counter.wrapping_add(1);
        true
    }
}

/// `plc-host/host.il` through build.rs, beside the host's functions.
pub mod host_build {
    use super::host_impl::{bump, clamp_sensor};
    include!(concat!(env!("OUT_DIR"), "/host/host.rs"));
}

/// The same through `il!(file = ...)`.
pub mod host_macro {
    use super::host_impl::{bump, clamp_sensor};
    il_macros::il!(file = "plc-host/host.il");
}

/// `plc-encodings`: CODESYS V2.3 exports in Windows code pages, through
/// build.rs (`Builder::encoding`) and `il!(..., encoding = ...)`; the
/// Windows-1252 one without a setting (read as Windows-1252 by default).
pub mod encodings_build {
    include!(concat!(env!("OUT_DIR"), "/encodings/nasos_1251.rs"));
}

/// The same through `il!`.
pub mod encodings_macro {
    il_macros::il!(
        file = "plc-encodings/nasos_1251.exp",
        encoding = "windows-1251"
    );
    il_macros::il!(file = "plc-encodings/anzeige_1252.exp");
}

/// `exp/project.EXP`: a CODESYS V2.3 export (Windows-1252) through
/// build.rs. Its `FUNCTION_BLOCK` `Scale` is in Structured Text, so its body
/// is the crate's: `fn Scale` beside the generated struct.
pub mod exp_build {
    include!(concat!(env!("OUT_DIR"), "/exp/project.rs"));

    /// `Scale`'s ST body, `o := i * 10;`, in Rust.
    #[allow(non_snake_case)]
    pub fn Scale(this: &mut Scale, _ctx: &mut il_std::Cycle) {
        this.o = this.i.wrapping_mul(10);
    }
}

/// `exp/host_blocks.EXP`: an ST block with a `VAR_IN_OUT`, called from IL,
/// and a CFC PROGRAM, their bodies in Rust.
pub mod exp_host_build {
    include!(concat!(env!("OUT_DIR"), "/exp_host/host_blocks.rs"));

    /// `sum := sum + x; calls := calls + 1;`: the in-out comes after the
    /// context.
    #[allow(non_snake_case)]
    pub fn Accumulate(this: &mut Accumulate, _ctx: &mut il_std::Cycle, sum: &mut i32) {
        *sum = sum.wrapping_add(i32::from(this.x));
        this.calls = this.calls.wrapping_add(1);
    }

    /// The CFC program's body.
    #[allow(non_snake_case)]
    pub fn Logger(this: &mut Logger, _ctx: &mut il_std::Cycle) {
        this.lines += 1;
    }
}

/// The same project through `il!`.
pub mod exp_macro {
    il_macros::il!(file = "exp/project.EXP", encoding = "windows-1252");

    /// `Scale`'s ST body, `o := i * 10;`, in Rust.
    #[allow(non_snake_case)]
    pub fn Scale(this: &mut Scale, _ctx: &mut il_std::Cycle) {
        this.o = this.i.wrapping_mul(10);
    }
}

/// `m221/groups.smbp`: a Modicon M221 project through build.rs.
pub mod m221_build {
    include!(concat!(env!("OUT_DIR"), "/m221/groups.rs"));
}

/// The same project through `il!`.
pub mod m221_macro {
    il_macros::il!(file = "m221/groups.smbp");
}

/// `m221/ends.smbp`: two POUs, `ENDC`/`ENDCN`, bits of words.
pub mod m221_ends {
    include!(concat!(env!("OUT_DIR"), "/m221_ends/ends.rs"));
}

/// `m221/listing.il`: a Modicon M221 / `TwidoSuite` text listing through
/// build.rs (`Builder::dialect`).
pub mod m221_listing_build {
    include!(concat!(env!("OUT_DIR"), "/m221_listing/listing.rs"));
}

/// The same listing through `il!(..., dialect = "m221")`.
pub mod m221_listing_macro {
    il_macros::il!(file = "m221/listing.il", dialect = "m221");
}

/// `logiclab/project.plcprj`: a `LogicLab` / Arduino PLC IDE project through
/// build.rs. Its `FUNCTION_BLOCK` `Scale` is in Structured Text, so its body
/// is the crate's.
pub mod logiclab_build {
    include!(concat!(env!("OUT_DIR"), "/logiclab/project.rs"));

    /// `Scale`'s ST body, `scaled := raw * k;` (k = 3), in Rust.
    #[allow(non_snake_case)]
    pub fn Scale(this: &mut Scale, _ctx: &mut il_std::Cycle) {
        this.scaled = this.raw.wrapping_mul(3);
    }
}

/// The same project through `il!`.
pub mod logiclab_macro {
    il_macros::il!(file = "logiclab/project.plcprj");

    /// `Scale`'s ST body, `scaled := raw * k;` (k = 3), in Rust.
    #[allow(non_snake_case)]
    pub fn Scale(this: &mut Scale, _ctx: &mut il_std::Cycle) {
        this.scaled = this.raw.wrapping_mul(3);
    }
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

/// `CounterIL`, the IL POU of Beremiz's `first_steps` `PLCopen` XML project
/// (`../shared/corpus/beremiz_beremiz_first_steps_plc.xml`).
#[cfg(il_plcopen_corpus)]
pub mod first_steps {
    include!(concat!(
        env!("OUT_DIR"),
        "/plcopen/beremiz_beremiz_first_steps_plc.rs"
    ));
}
