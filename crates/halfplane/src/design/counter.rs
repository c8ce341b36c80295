//! The counter-based generator and the keyed permutation behind random and Latin-hypercube
//! designs: every number is a pure function of its key and counter (see the parent module).

/// Stream purposes: the uniform draw of an axis, and the round keys of its permutation.
pub(super) const JITTER: u64 = 0;
pub(super) const PERMUTE: u64 = 1;

pub(super) fn stream(axis: usize, purpose: u64) -> u64 {
    ((axis as u64) << 1) | purpose
}

/// The SplitMix64 finaliser: a bijection of u64 with full avalanche (Steele, Lea & Flood 2014).
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The counter-based hash of `(seed, stream, counter)`.
fn hash(seed: u64, stream: u64, counter: u64) -> u64 {
    const GOLDEN: u64 = 0x9e37_79b9_7f4a_7c15;
    let key = mix(seed.wrapping_add(GOLDEN));
    let key = mix(key ^ stream.wrapping_mul(GOLDEN));
    mix(key ^ counter.wrapping_mul(0xd1b5_4a32_d192_ed03))
}

/// A uniform number in [0, 1) from `(seed, stream, counter)`: the hash's top 53 bits.
pub(super) fn unit(seed: u64, stream: u64, counter: u64) -> f64 {
    (hash(seed, stream, counter) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// A keyed bijection of `0..n`: a balanced Feistel network on `0..4^h` (the smallest such domain
/// holding `n`), restricted to `0..n` by cycle-walking.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Permutation {
    n: u64,
    half_bits: u32,
    keys: [u64; 4],
}

impl Permutation {
    pub(super) fn new(n: u64, seed: u64, axis: u64) -> Self {
        let bits = 64 - n.saturating_sub(1).leading_zeros();
        let half_bits = bits.div_ceil(2).max(1);
        let s = stream(axis as usize, PERMUTE);
        let keys = [0, 1, 2, 3].map(|round| hash(seed, s, round));
        Self { n, half_bits, keys }
    }

    /// One pass of the Feistel network over `0..4^h`.
    fn feistel(&self, x: u64) -> u64 {
        let mask = (1u64 << self.half_bits) - 1;
        let (mut left, mut right) = (x >> self.half_bits, x & mask);
        for key in self.keys {
            let f = mix(right ^ key) & mask;
            (left, right) = (right, left ^ f);
        }
        (left << self.half_bits) | right
    }

    /// The image of `i < n`: walk the network's cycle through `i` until it is back in `0..n`.
    pub(super) fn apply(&self, i: u64) -> u64 {
        let mut x = self.feistel(i);
        while x >= self.n {
            x = self.feistel(x);
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn feistel_walk_is_a_bijection_of_every_size() {
        for n in [1u64, 2, 3, 4, 5, 7, 16, 17, 1000, 1025, 4096] {
            for seed in [0, 1, 0xdead_beef] {
                let p = Permutation::new(n, seed, 3);
                let mut seen = vec![false; n as usize];
                for i in 0..n {
                    let k = p.apply(i) as usize;
                    assert!(!seen[k], "n = {n}, seed = {seed}: {k} hit twice");
                    seen[k] = true;
                }
            }
        }
    }
}
