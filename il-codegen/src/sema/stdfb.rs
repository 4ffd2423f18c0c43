//! Interfaces of the standard function blocks of il-std, as the checker needs
//! them: inputs and outputs with their IEC names and types.

use super::types::Elem::{self, *};

pub struct StdFb {
    pub name: &'static str,
    pub inputs: &'static [(&'static str, Elem)],
    pub outputs: &'static [(&'static str, Elem)],
}

macro_rules! counters {
    ($($ctu:literal $ctd:literal $ctud:literal $t:ident;)*) => {
        &[$(
            StdFb { name: $ctu, inputs: &[("CU", BOOL), ("R", BOOL), ("PV", $t)], outputs: &[("Q", BOOL), ("CV", $t)] },
            StdFb { name: $ctd, inputs: &[("CD", BOOL), ("LD", BOOL), ("PV", $t)], outputs: &[("Q", BOOL), ("CV", $t)] },
            StdFb {
                name: $ctud,
                inputs: &[("CU", BOOL), ("CD", BOOL), ("R", BOOL), ("LD", BOOL), ("PV", $t)],
                outputs: &[("QU", BOOL), ("QD", BOOL), ("CV", $t)],
            },
        )*]
    };
}

static COUNTERS: &[StdFb] = counters! {
    "CTU" "CTD" "CTUD" INT;
    "CTU_DINT" "CTD_DINT" "CTUD_DINT" DINT;
    "CTU_LINT" "CTD_LINT" "CTUD_LINT" LINT;
    "CTU_UDINT" "CTD_UDINT" "CTUD_UDINT" UDINT;
    "CTU_ULINT" "CTD_ULINT" "CTUD_ULINT" ULINT;
};

static OTHERS: &[StdFb] = &[
    StdFb {
        name: "SR",
        inputs: &[("S1", BOOL), ("R", BOOL)],
        outputs: &[("Q1", BOOL)],
    },
    StdFb {
        name: "RS",
        inputs: &[("S", BOOL), ("R1", BOOL)],
        outputs: &[("Q1", BOOL)],
    },
    StdFb {
        name: "R_TRIG",
        inputs: &[("CLK", BOOL)],
        outputs: &[("Q", BOOL)],
    },
    StdFb {
        name: "F_TRIG",
        inputs: &[("CLK", BOOL)],
        outputs: &[("Q", BOOL)],
    },
    StdFb {
        name: "TP",
        inputs: &[("IN", BOOL), ("PT", TIME)],
        outputs: &[("Q", BOOL), ("ET", TIME)],
    },
    StdFb {
        name: "TON",
        inputs: &[("IN", BOOL), ("PT", TIME)],
        outputs: &[("Q", BOOL), ("ET", TIME)],
    },
    StdFb {
        name: "TOF",
        inputs: &[("IN", BOOL), ("PT", TIME)],
        outputs: &[("Q", BOOL), ("ET", TIME)],
    },
    StdFb {
        name: "RTC",
        inputs: &[("IN", BOOL), ("PDT", DT)],
        outputs: &[("Q", BOOL), ("CDT", DT)],
    },
];

/// Look a standard FB up by name (case-insensitive).
pub fn lookup(name: &str) -> Option<&'static StdFb> {
    COUNTERS
        .iter()
        .chain(OTHERS)
        .find(|f| f.name.eq_ignore_ascii_case(name))
}
