//! M221 / TwidoSuite listings (`Dialect::M221`) never make the import
//! panic, and every diagnostic it gives lies inside the listing: the
//! listing of the tests (`tests/m221/listing.il`) mutated, and token soup
//! from the M221 vocabulary, with comments, configuration comments,
//! multi-byte characters and unclosed comments, all checked and rendered.
//! The scan-by-scan behaviour is il-cli's `m221_listing` test.

use il_codegen::diag::SourceFile;
use il_codegen::{Dialect, Program};

/// xorshift64* (as in `front_end_robustness`).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

#[rustfmt::skip]
const VOCAB: &[&str] = &[
    "LD", "LDN", "LDR", "LDF", "AND", "ANDN", "ANDR", "OR", "ORN", "XOR", "ST", "STN", "S", "R",
    "N", "AND(", "OR(", "AND(N", ")", "MPS", "MRD", "MPP", "BLK", "OUT_BLK", "END_BLK", "IN", "Q",
    "CU", "CD", "D", "JMP", "JMPC", "JMPCN", "END", "ENDC", "ENDCN", "CAL", "RET", "RETC", "RETCN",
    "SR0", "SR1", "SR1:", "SR300:", "%L1:", "%L1", "%L99:", "%I0.0", "%I1.40", "%Q0.3", "%M5",
    "%MW2", "%MW2:X3", "%MD4", "%MF4", "%KW0", "%KW9", "%TM0", "%TM0.Q", "%TM0.V", "%C0", "%C0.V",
    "%R0", "%DR0", "%SBR0.3", "%SC0.200", "%S0", "%S6", "%S8", "%SW7", "%FC0", "[", "]", ":=",
    "+", "-", "*", "/", ">=", "<>", "SQRT(", "1", "0", "#FF", "2.5", "-3", "12", "(*", "*)",
    "(* ä *)", "(*@ %TM0 TON BASE=10ms PRESET=3 *)", "(*@ %C0 PRESET=2 *)", "(*@ %KW0 VALUE=1 *)",
    "(*@ %TM1 BASE=3ms *)", "(*@ %R0 LIFO *)", "(*@", "(*@ *)", "\n", "\n", "\n\n", " ", "\t", "Ω",
];

fn check(text: String) {
    let file = SourceFile::new("listing.il", text.clone());
    let checked = Program::new().input(Dialect::M221.input(file)).check();
    for (input, diags) in checked.reports() {
        for d in diags {
            let (lo, hi) = (d.span.lo as usize, d.span.hi as usize);
            assert!(
                lo <= hi && hi <= text.len(),
                "{} at {lo}..{hi} outside the listing ({} bytes):\n{text}",
                d.code,
                text.len()
            );
            assert!(
                text.is_char_boundary(lo) && text.is_char_boundary(hi),
                "{text}"
            );
        }
        let _ = il_codegen::diag::render(input.source(), diags, false);
    }
}

#[test]
fn no_listing_makes_the_import_panic() {
    let base = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/m221/listing.il"),
    )
    .expect("tests/m221/listing.il");
    // The listing itself checks clean.
    let file = SourceFile::new("listing.il", base.clone());
    let checked = Program::new().input(Dialect::M221.input(file)).check();
    assert!(
        checked.diagnostics().iter().all(|d| d.is_empty()),
        "{}",
        checked.render(false)
    );
    let lines: Vec<&str> = base.lines().collect();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for _ in 0..1500 {
        // Mutations: lines dropped, doubled, swapped, cut, or a word put in.
        let mut ls: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        for _ in 0..1 + rng.below(4) {
            let k = rng.below(ls.len());
            match rng.below(5) {
                0 => {
                    ls.remove(k);
                }
                1 => ls.insert(k, ls[k].clone()),
                2 => {
                    let j = rng.below(ls.len());
                    ls.swap(k, j);
                }
                3 => {
                    let l = &ls[k];
                    let mut cut = rng.below(l.len() + 1);
                    while !l.is_char_boundary(cut) {
                        cut -= 1;
                    }
                    ls[k] = l[..cut].to_string();
                }
                _ => {
                    let w = VOCAB[rng.below(VOCAB.len())];
                    ls[k] = format!("{} {w}", ls[k]);
                }
            }
            if ls.is_empty() {
                break;
            }
        }
        check(ls.join("\n"));
    }
    for _ in 0..1500 {
        let n = 1 + rng.below(40);
        let soup: Vec<&str> = (0..n).map(|_| VOCAB[rng.below(VOCAB.len())]).collect();
        check(soup.join(" "));
    }
}
