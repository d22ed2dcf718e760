//! The leaves of a basin certificate as a partition of its box (rule B3,
//! docs/basin-certificates.md §3): each path is a sequence of bisections, digit 2k the lower and
//! 2k + 1 the upper half of coordinate k; the paths must be the leaves of one binary tree in
//! which every internal node halves one coordinate for both its children. Then the leaves'
//! boxes are pairwise disjoint up to their boundaries and cover the box, and the share of a leaf
//! is 2^-(length of its path).

/// A node of the tree being rebuilt.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Node {
    /// Not reached by any path yet.
    Open,
    /// A leaf.
    Leaf,
    /// Halves `axis`; the children's indices.
    Split(u8, [usize; 2]),
}

/// Why the paths are not a partition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TreeError {
    /// A character that is not a digit 0..2D-1 (the leaf, the position).
    Digit(usize, usize),
    /// Leaf `.0` overlaps an earlier leaf (its path extends a leaf, or equals or prefixes a path).
    Overlap(usize),
    /// Leaf `.0` halves another coordinate where an earlier path halved a different one.
    Axis(usize),
    /// Some part of the box is in no leaf.
    Uncovered,
}

/// Checks that `paths` (over `dims` coordinates) are the leaves of one bisection tree covering
/// the box.
pub fn partition<'a>(paths: impl IntoIterator<Item = &'a str>, dims: usize) -> Result<(), TreeError> {
    let mut nodes = vec![Node::Open];
    for (leaf, path) in paths.into_iter().enumerate() {
        let mut at = 0;
        for (pos, ch) in path.bytes().enumerate() {
            let digit = ch.wrapping_sub(b'0') as usize;
            if !ch.is_ascii_digit() || digit >= 2 * dims {
                return Err(TreeError::Digit(leaf, pos));
            }
            let axis = (digit / 2) as u8;
            let children = match nodes[at] {
                Node::Leaf => return Err(TreeError::Overlap(leaf)),
                Node::Split(a, _) if a != axis => return Err(TreeError::Axis(leaf)),
                Node::Split(_, c) => c,
                Node::Open => {
                    let c = [nodes.len(), nodes.len() + 1];
                    nodes.extend([Node::Open, Node::Open]);
                    nodes[at] = Node::Split(axis, c);
                    c
                }
            };
            at = children[digit % 2];
        }
        if nodes[at] != Node::Open {
            return Err(TreeError::Overlap(leaf));
        }
        nodes[at] = Node::Leaf;
    }
    if nodes.contains(&Node::Open) { Err(TreeError::Uncovered) } else { Ok(()) }
}
