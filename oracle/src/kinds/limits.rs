//! The limits of docs/certificate-format.md §2 ("Limits"), at their defaults.

/// The work a file may ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// `max-digits`: digits of one number (numerator and denominator together).
    pub max_digits: usize,
    /// `max-total-digits`: characters of all the numbers of a file together.
    pub max_total_digits: usize,
    /// `max-generators`: generators of one cone (points of a refutation).
    pub max_generators: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits { max_digits: 10_000, max_total_digits: 2_000_000, max_generators: 100_000 }
    }
}
