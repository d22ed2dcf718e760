//! Helpers for the simulator's generated English text (decision descriptions and pattern
//! summaries); depends on no other simulator module.

/// Singular for one impact in generated text.
pub fn singular(s: String) -> String {
    s.replace(" 1 impacts", " 1 impact").replace("(1 impacts", "(1 impact")
}
