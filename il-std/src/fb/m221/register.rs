//! `%Rn`, the LIFO/FIFO register of the M221: a memory of up to 16 words of 16 bits, as a
//! queue (FIFO) or a stack (LIFO); which of the two is the register's configuration, so it is
//! one block type each.

use super::rising;
use crate::cycle::Cycle;

/// The register's capacity in words, from the manual.
const CAPACITY: usize = 16;

macro_rules! register {
    ($name:ident, $lifo:literal, $what:literal, $example_out:literal) => {
        #[doc = concat!("`", stringify!($name), "`: the register `%Rn` of a Modicon M221 / Twido configured as ", $what, ".")]
        ///
        /// From the manual: `R` at 1 initialises the register (empties it; `E` goes to 1); a
        /// rising edge of `I` stores the word `IW` (`%Rn.I`) in the register, and does nothing
        /// when it is full; a rising edge of `O` loads a word of the register into `OW`
        /// (`%Rn.O`) — the oldest one of a FIFO, the newest one of a LIFO — and when the
        /// register is empty `OW` keeps its value; `E` is 1 while the register is empty, `F`
        /// while it holds 16 words. `%Rn.I` and `%Rn.O` may be written by the program.
        ///
        /// This crate's choices where the manual is silent: `R` has priority (a storage or
        /// retrieval edge in the same call is lost); when `I` and `O` rise in the same call the
        /// word is stored first, then one is retrieved; `OW` keeps its value through `R`.
        ///
        /// ```
        #[doc = concat!("use il_std::{Cycle, ", stringify!($name), "};")]
        /// let mut ctx = Cycle::new();
        #[doc = concat!("let mut r = ", stringify!($name), "::new();")]
        /// assert!(r.E);
        /// for w in [10, 20] {
        ///     r.IW = w;
        ///     r.I = true; r.call(&mut ctx);
        ///     r.I = false; r.call(&mut ctx);
        /// }
        /// r.O = true; r.call(&mut ctx);
        #[doc = concat!("assert_eq!((r.OW, r.E), (", $example_out, ", false));")]
        /// ```
        #[derive(Clone, Debug, PartialEq)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub struct $name {
            /// Input: at 1, empty the register (priority over `I` and `O`).
            pub R: bool,
            /// Input: store `IW` on its rising edge.
            pub I: bool,
            /// Input: retrieve a word into `OW` on its rising edge.
            pub O: bool,
            /// Input: the word to store (`%Rn.I`).
            pub IW: i16,
            /// Input and output: the word last retrieved (`%Rn.O`); the program may write it.
            pub OW: i16,
            /// Output: the register is empty (`%Rn.E`).
            pub E: bool,
            /// Output: the register holds 16 words (`%Rn.F`).
            pub F: bool,
            i_m: bool,
            o_m: bool,
            /// The words, oldest first.
            words: [i16; CAPACITY],
            len: u8,
        }

        impl Default for $name {
            fn default() -> Self {
                Self::new()
            }
        }

        impl $name {
            /// An empty register (`E` is 1, as after a cold start).
            pub const fn new() -> Self {
                Self {
                    R: false,
                    I: false,
                    O: false,
                    IW: 0,
                    OW: 0,
                    E: true,
                    F: false,
                    i_m: false,
                    o_m: false,
                    words: [0; CAPACITY],
                    len: 0,
                }
            }

            /// Runs the block body once.
            pub fn call(&mut self, _ctx: &mut Cycle) {
                let store = rising(self.I, &mut self.i_m);
                let retrieve = rising(self.O, &mut self.o_m);
                if self.R {
                    self.len = 0;
                } else {
                    let n = usize::from(self.len);
                    if store && n < CAPACITY {
                        self.words[n] = self.IW;
                        self.len += 1;
                    }
                    let n = usize::from(self.len);
                    if retrieve && n > 0 {
                        if $lifo {
                            self.OW = self.words[n - 1];
                        } else {
                            self.OW = self.words[0];
                            self.words.copy_within(1..n, 0);
                        }
                        self.len -= 1;
                    }
                }
                self.E = self.len == 0;
                self.F = usize::from(self.len) == CAPACITY;
            }
        }
    };
}

register!(M221_FIFO, false, "a FIFO (queue)", "10");
register!(M221_LIFO, true, "a LIFO (stack)", "20");

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// One call per `(R, I, O, IW)`; returns `(OW, E, F)` after each.
    macro_rules! run {
        ($t:ty, $seq:expr) => {{
            let mut c = Cycle::new();
            let mut r = <$t>::new();
            $seq.iter()
                .map(|&(rr, i, o, iw)| {
                    r.R = rr;
                    r.I = i;
                    r.O = o;
                    r.IW = iw;
                    r.call(&mut c);
                    (r.OW, r.E, r.F)
                })
                .collect::<Vec<_>>()
        }};
    }

    const NONE: (bool, bool, bool, i16) = (false, false, false, 0);

    fn store(w: i16) -> [(bool, bool, bool, i16); 2] {
        [(false, true, false, w), NONE]
    }

    fn retrieve() -> [(bool, bool, bool, i16); 2] {
        [(false, false, true, 0), NONE]
    }

    #[test]
    fn fifo_gives_the_oldest_word_and_lifo_the_newest() {
        let seq: Vec<_> = [store(1), store(2), store(3), retrieve(), retrieve()].concat();
        let fifo = run!(M221_FIFO, seq);
        let lifo = run!(M221_LIFO, seq);
        // After the first retrieval (call 7) and the second (call 9).
        assert_eq!((fifo[6].0, fifo[8].0), (1, 2));
        assert_eq!((lifo[6].0, lifo[8].0), (3, 2));
        // One word left: not empty.
        assert!(!fifo[9].1 && !lifo[9].1);
    }

    #[test]
    fn retrieving_from_an_empty_register_keeps_the_output_word() {
        let seq: Vec<_> = [store(7), retrieve(), retrieve()].concat();
        let got = run!(M221_FIFO, seq);
        assert_eq!(got[0], (0, false, false)); // stored on the edge
        assert_eq!(got[2], (7, true, false)); // retrieved: now empty
        assert_eq!(got[4], (7, true, false)); // empty: OW kept
    }

    #[test]
    fn full_after_sixteen_words_and_a_seventeenth_is_not_stored() {
        let mut seq: Vec<_> = (1..=17).flat_map(store).collect();
        seq.extend((0..16).flat_map(|_| retrieve()));
        let got = run!(M221_FIFO, seq);
        assert_eq!(got[29], (0, false, false)); // 15 words
        assert_eq!(got[31], (0, false, true)); // 16th word: full
        assert_eq!(got[33], (0, false, true)); // 17th refused
        // The sixteen words come out in order; the 17th never went in.
        let outs: Vec<i16> = (0..16).map(|k| got[34 + 2 * k].0).collect();
        assert_eq!(outs, (1..=16).collect::<Vec<i16>>());
        assert_eq!(got[64], (16, true, false));
    }

    #[test]
    fn reset_empties_and_has_priority_over_an_edge() {
        let seq: Vec<_> = [
            &store(5)[..],
            &store(6)[..],
            &[(true, true, false, 9)][..], // R with I's edge: emptied, 9 not stored
            &[NONE][..],
            &retrieve()[..],
        ]
        .concat();
        let got = run!(M221_LIFO, seq);
        assert_eq!(got[4], (0, true, false));
        assert_eq!(got[6], (0, true, false)); // nothing to retrieve: OW kept (0)
    }

    #[test]
    fn store_then_retrieve_in_one_call() {
        // Empty register, I and O rise together: the word goes in and comes out.
        let got = run!(M221_FIFO, [(false, true, true, 42)]);
        assert_eq!(got[0], (42, true, false));
    }

    #[test]
    fn edge_inputs_count_once_while_held() {
        let seq = [
            (false, true, false, 1),
            (false, true, false, 2),
            (false, true, false, 3),
        ];
        let got = run!(M221_LIFO, seq);
        assert!(!got[2].1);
        let mut r = M221_LIFO::new();
        let mut c = Cycle::new();
        for &(rr, i, o, iw) in &seq {
            r.R = rr;
            r.I = i;
            r.O = o;
            r.IW = iw;
            r.call(&mut c);
        }
        assert_eq!(r.len, 1);
    }
}
