//! Compiles the IL test programs through the build-script front end.
//! `plc/*.il` are ours; the Annex F programs are read from `../shared/corpus`
//! when it is present (they are GPL test inputs and are never copied into
//! the repository), which enables `cfg(il_corpus)`. The PLCopen XML project
//! of the corpus (Beremiz's first_steps) goes through
//! `Builder::plcopen_file` and enables `cfg(il_plcopen_corpus)`.

use std::path::{Path, PathBuf};

fn main() {
    println!("cargo::rustc-check-cfg=cfg(il_corpus)");
    println!("cargo::rustc-check-cfg=cfg(il_plcopen_corpus)");
    let mut files: Vec<PathBuf> = std::fs::read_dir("plc")
        .expect("tests/plc exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    files.sort();
    println!("cargo:rerun-if-changed=plc");
    // serde derives on everything the build.rs front end generates here (the
    // il! copies in via_macro have none): it must compile for every program.
    let generated = il_codegen::Builder::new()
        .files(&files)
        .serde(true)
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));
    // One index per front end, so both run the same programs.
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    let mut by_build = String::new();
    let mut by_macro = String::new();
    for (src, rs) in files.iter().zip(&generated) {
        by_build.push_str(&format!("include!({:?});\n", rs.display().to_string()));
        by_macro.push_str(&format!(
            "il_macros::il!(file = {:?});\n",
            src.display().to_string()
        ));
    }
    std::fs::write(out.join("generated_index.rs"), by_build).expect("write index");
    std::fs::write(out.join("macro_index.rs"), by_macro).expect("write index");

    // Hostile names (tests/hostile.rs) in a program of their own: POUs named
    // `Some`, `Option`, `Default`, `Result` would shadow the prelude in test
    // files that glob-import the modules of the other programs.
    println!("cargo:rerun-if-changed=plc-hostile");
    il_codegen::Builder::new()
        .file("plc-hostile/hostile.il")
        .out_dir(out.join("hostile"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));

    // Host functions ({extern}): the crate provides their bodies
    // (src/lib.rs, host_impl), so they get modules of their own.
    println!("cargo:rerun-if-changed=plc-host");
    il_codegen::Builder::new()
        .file("plc-host/host.il")
        .out_dir(out.join("host"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));

    // A CODESYS V2.3 export in Windows-1251 (Russian comments and a STRING
    // literal): read in the encoding the build names.
    println!("cargo:rerun-if-changed=plc-encodings");
    il_codegen::Builder::new()
        .file("plc-encodings/nasos_1251.exp")
        .encoding("windows-1251")
        .out_dir(out.join("encodings"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));

    // A CODESYS V2.3 project (.EXP, Windows-1252) whose FUNCTION_BLOCK
    // `Scale` is in ST: host-provided, the crate supplies its body
    // (src/lib.rs, exp_build).
    println!("cargo:rerun-if-changed=exp");
    il_codegen::Builder::new()
        .file("exp/project.EXP")
        .encoding("windows-1252")
        .out_dir(out.join("exp"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));
    // Host blocks with an in-out and a host PROGRAM (CFC), bodies in
    // src/lib.rs (exp_host_build).
    il_codegen::Builder::new()
        .file("exp/host_blocks.EXP")
        .out_dir(out.join("exp_host"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));

    // A LogicLab / Arduino PLC IDE project (.plcprj) whose FUNCTION_BLOCK
    // `Scale` is in ST: host-provided, body in src/lib.rs (logiclab_build).
    println!("cargo:rerun-if-changed=logiclab");
    il_codegen::Builder::new()
        .file("logiclab/project.plcprj")
        .out_dir(out.join("logiclab"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));

    // A Modicon M221 project (.smbp): its rungs' Instruction List and its
    // objects as a CONFIGURATION (tests/m221.rs).
    println!("cargo:rerun-if-changed=m221");
    il_codegen::Builder::new()
        .file("m221/groups.smbp")
        .out_dir(out.join("m221"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));
    il_codegen::Builder::new()
        .file("m221/ends.smbp")
        .out_dir(out.join("m221_ends"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));
    // A TwidoSuite / Machine Expert Basic text listing (`Builder::dialect`).
    il_codegen::Builder::new()
        .file("m221/listing.il")
        .dialect(il_codegen::Dialect::M221)
        .out_dir(out.join("m221_listing"))
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));

    let corpus = Path::new("../../shared/corpus");
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    if corpus.join("beremiz_matiec_cmd_monitor_il.txt").exists() {
        println!("cargo:rustc-cfg=il_corpus");
        // FWD_REV_MON reads FWD_REV_FF.Q, but an SR's output is Q1 (the
        // checker refuses it; see tests/annex_f.rs). Compile a corrected copy.
        let fwd = std::fs::read_to_string(corpus.join("beremiz_matiec_fwd_rev_mon_il.txt"))
            .expect("read");
        let fixed = out.join("fwd_rev_mon_fixed.il");
        std::fs::write(&fixed, fwd.replace("FWD_REV_FF.Q\t", "FWD_REV_FF.Q1\t")).expect("write");
        let dir = out.join("annex_f");
        il_codegen::Builder::new()
            .file(corpus.join("beremiz_matiec_cmd_monitor_il.txt"))
            .file(corpus.join("beremiz_matiec_stack_int_il.txt"))
            .file(corpus.join("beremiz_matiec_weigh_il.txt"))
            .file(&fixed)
            .out_dir(&dir)
            .compile()
            .unwrap_or_else(|e| panic!("\n{e}"));
    } else {
        println!("cargo:warning=../shared/corpus not found: Annex F tests are skipped");
    }
    let first_steps = corpus.join("beremiz_beremiz_first_steps_plc.xml");
    if first_steps.exists() {
        println!("cargo:rustc-cfg=il_plcopen_corpus");
        // Its CounterIL is the only IL POU; the others (ST, FBD, LD, SFC)
        // and the configuration (which runs the FBD plc_prg) are left out
        // with warnings (shown as cargo warnings on a fresh build).
        il_codegen::Builder::new()
            .plcopen_file(&first_steps)
            .out_dir(out.join("plcopen"))
            .compile()
            .unwrap_or_else(|e| panic!("\n{e}"));
    } else {
        println!("cargo:warning=../shared/corpus not found: PLCopen tests are skipped");
    }
}
