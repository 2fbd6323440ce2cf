//! The two seeded pseudo-random generators, side by side. Both are deterministic (the same seed gives the
//! same sequence on every platform) and neither is cryptographic.
//!
//! | generator | used by | why this one |
//! | --- | --- | --- |
//! | [`Lcg`] | the example curve networks (`network::examples`), tests | its sequence *defines* the example networks and the demos' presets: replacing it would change them |
//! | [`SplitMix64`] | noisy data (`fit::noisy_curve`: uniform and Gaussian draws) | passes BigCrush; its sequence defines the seeded data sets of the noisy-data demo |
//!
//! They are not merged into one: each sequence is part of a documented, seeded output (an example network
//! or a data set reproducible from its seed), so either replacement would change results that links and
//! tests pin.

use glam::DVec3;

/// A 64-bit linear congruential generator (Knuth's MMIX multiplier and increment; values in [−1, 1) from
/// the top 53 bits). Statistically weak but enough for perturbing example networks; kept because its
/// sequence defines the example networks (`network::examples`) — another generator would change them.
pub struct Lcg(u64);
impl Lcg {
    /// A generator seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        Lcg(seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407))
    }
    /// The next value, in [−1, 1).
    #[allow(
        clippy::should_implement_trait,
        reason = "an endless f64 stream: as an Iterator every call site would unwrap an Option"
    )]
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    /// A point with three coordinates in [−1, 1).
    pub fn point(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }
}

/// SplitMix64 (Steele, Lea, Flood 2014): 64-bit state, passes BigCrush, one multiply-xorshift per draw.
#[derive(Debug, Clone)]
pub struct SplitMix64 {
    state: u64,
    spare: Option<f64>,
}

impl SplitMix64 {
    /// A generator seeded with `seed` (the same seed, the same sequence).
    pub fn new(seed: u64) -> Self {
        SplitMix64 {
            state: seed,
            spare: None,
        }
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1) with 53 random bits.
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    /// Standard normal by the Box–Muller transform (the second value of each pair is kept for the next call).
    pub fn gaussian(&mut self) -> f64 {
        if let Some(z) = self.spare.take() {
            return z;
        }
        let u1 = 1.0 - self.uniform(); // (0, 1]
        let u2 = self.uniform();
        let r = (-2.0 * u1.ln()).sqrt();
        let th = 2.0 * std::f64::consts::PI * u2;
        self.spare = Some(r * th.sin());
        r * th.cos()
    }
}
