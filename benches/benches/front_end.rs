//! Group 1, front end: parse, check (sema) and emit separately, and the
//! whole `il_codegen::compile`, on one generated POU of 1k, 10k and 100k
//! lines and on programs of many small POUs. Each benchmark counts IL lines
//! as its items, so divan's throughput column (items/s) gives lines per
//! second: equal throughput at every size means linear growth.
//!
//! `cargo bench -p il-bench --bench front_end`

use divan::counter::ItemsCount;
use divan::{Bencher, black_box};
use il_bench::generator;
use il_codegen::EmitOptions;
use il_codegen::diag::SourceFile;

fn main() {
    divan::main();
}

const LINES: [usize; 3] = [1_000, 10_000, 100_000];
/// Small POUs of about 20 lines each: 50 (1k lines) and 500 (10k lines).
const POUS: [usize; 2] = [50, 500];

fn big(lines: usize) -> SourceFile {
    SourceFile::new("big.il", generator::big_pou(lines, 1))
}

fn labels(lines: usize) -> SourceFile {
    SourceFile::new("labels.il", generator::big_pou_labels(lines, 1))
}

fn straight(lines: usize) -> SourceFile {
    SourceFile::new("straight.il", generator::big_pou_straight(lines, 1))
}

fn many(pous: usize) -> SourceFile {
    SourceFile::new("many.il", generator::many_pous(pous, 1))
}

fn lines_of(f: &SourceFile) -> ItemsCount {
    ItemsCount::new(f.text.lines().count())
}

fn bench_parse(b: Bencher, file: SourceFile) {
    b.counter(lines_of(&file))
        .bench_local(|| il_codegen::ast::parse(black_box(&file)));
}

/// Parse and check through the pipeline (the checker is private: the
/// check alone is this less `parse`).
fn bench_check(b: Bencher, file: SourceFile) {
    b.counter(lines_of(&file)).bench_local(|| {
        il_codegen::Program::new()
            .il(black_box(&file).clone())
            .check()
    });
}

fn bench_emit(b: Bencher, file: SourceFile) {
    let checked = il_codegen::Program::new().il(file.clone()).check();
    assert!(!checked.has_errors());
    b.counter(lines_of(&file))
        .bench_local(|| black_box(&checked).emit(EmitOptions::default()));
}

fn bench_whole(b: Bencher, file: SourceFile) {
    b.counter(lines_of(&file)).bench_local(|| {
        let program = il_codegen::Program::new().il(black_box(&file).clone());
        let checked = program.check();
        let mut emitted = checked
            .emit(EmitOptions::default())
            .expect("generated IL compiles");
        emitted.remove(0).text
    });
}

/// What a build script does: compile with line markers and format the
/// `.rs` text (the emitted text with the IL lines as comments).
fn bench_to_file(b: Bencher, file: SourceFile) {
    b.counter(lines_of(&file)).bench_local(|| {
        il_codegen::Program::new()
            .il(black_box(&file).clone())
            .check()
            .files(EmitOptions::default())
            .expect("generated IL compiles")
    });
}

/// One POU of N lines.
mod one_pou {
    use super::*;

    #[divan::bench(args = LINES, max_time = 4)]
    fn parse(b: Bencher, lines: usize) {
        bench_parse(b, big(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn check(b: Bencher, lines: usize) {
        bench_check(b, big(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn emit(b: Bencher, lines: usize) {
        bench_emit(b, big(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn whole(b: Bencher, lines: usize) {
        bench_whole(b, big(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn whole_to_file(b: Bencher, lines: usize) {
        bench_to_file(b, big(lines));
    }
}

/// One POU in MATIEC's style: a label every 45 lines (about 2,200 in
/// 100k lines) and jumps between them, forward and backward. Up to 1M
/// lines for parse and check, to show they stay linear.
mod many_labels {
    use super::*;

    const LABEL_LINES: [usize; 3] = [10_000, 100_000, 1_000_000];

    #[divan::bench(args = LABEL_LINES, max_time = 4)]
    fn parse(b: Bencher, lines: usize) {
        bench_parse(b, labels(lines));
    }
    #[divan::bench(args = LABEL_LINES, max_time = 4)]
    fn check(b: Bencher, lines: usize) {
        bench_check(b, labels(lines));
    }
    #[divan::bench(args = [10_000, 100_000], max_time = 4)]
    fn whole(b: Bencher, lines: usize) {
        bench_whole(b, labels(lines));
    }
    /// `ilc check` of the file in process (issue 14's 0.15 s row at 100k
    /// lines): the pipeline's check and every diagnostic rendered for the
    /// terminal (the generator's unused labels are warnings).
    #[divan::bench(args = [10_000, 100_000], max_time = 4)]
    fn ilc_check(b: Bencher, lines: usize) {
        let file = labels(lines);
        b.counter(lines_of(&file)).bench_local(|| {
            let checked = il_codegen::Program::new()
                .il(black_box(&file).clone())
                .check();
            checked.render(false)
        });
    }
    /// `ilc emit FILE -o DIR` in process (the 0.3 s row): check, the syntax
    /// tree dropped, the warnings rendered and the `.rs` text with the IL
    /// lines as comments (`Checked::files`, what the file writer writes)
    /// written (the file is removed first, so every iteration writes it).
    #[divan::bench(args = [10_000, 100_000], max_time = 4)]
    fn ilc_emit(b: Bencher, lines: usize) {
        let file = labels(lines);
        let dir = std::env::temp_dir().join(format!("il-bench-ilc-emit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temporary directory");
        let path = dir.join("labels.rs");
        b.counter(lines_of(&file)).bench_local(|| {
            let _ = std::fs::remove_file(&path);
            let mut checked = il_codegen::Program::new()
                .il(black_box(&file).clone())
                .check();
            checked.drop_syntax();
            black_box(checked.render(false));
            let texts = checked
                .files(EmitOptions::default())
                .expect("generated IL compiles");
            il_codegen::write_if_changed(&path, &texts[0]).expect("written");
        });
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The same POU without labels and jumps: what check costs without the
/// label fixpoint's repeated passes.
mod one_pou_straight {
    use super::*;

    #[divan::bench(args = LINES, max_time = 4)]
    fn parse(b: Bencher, lines: usize) {
        bench_parse(b, straight(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn check(b: Bencher, lines: usize) {
        bench_check(b, straight(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn emit(b: Bencher, lines: usize) {
        bench_emit(b, straight(lines));
    }
    #[divan::bench(args = LINES, max_time = 4)]
    fn whole(b: Bencher, lines: usize) {
        bench_whole(b, straight(lines));
    }
}

/// N small FUNCTION_BLOCKs of about 20 lines each in one file.
mod many_pous {
    use super::*;

    #[divan::bench(args = POUS, max_time = 3)]
    fn parse(b: Bencher, pous: usize) {
        bench_parse(b, many(pous));
    }
    #[divan::bench(args = POUS, max_time = 3)]
    fn check(b: Bencher, pous: usize) {
        bench_check(b, many(pous));
    }
    #[divan::bench(args = POUS, max_time = 3)]
    fn emit(b: Bencher, pous: usize) {
        bench_emit(b, many(pous));
    }
    #[divan::bench(args = POUS, max_time = 3)]
    fn whole(b: Bencher, pous: usize) {
        bench_whole(b, many(pous));
    }
}
