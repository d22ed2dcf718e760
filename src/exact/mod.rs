//! Exact scalars for the tool: everything of [`chatter_kernel::exact`], plus untrusted
//! conveniences the kernel must not have: numbers typed by a user (decimals, scientific
//! notation) and conversions between rationals and floats or rounded decimals.

mod float;
mod user;

pub use chatter_kernel::exact::*;
pub use float::{QExt, Rounding};
pub use user::parse_user_number;
