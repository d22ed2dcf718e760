//! The dicts of `classify`, `simulate`, `bodies` and `map`: each is one `serde_json::Value` made
//! by one function (`value`), the fields of the command's `--json` output. Until the library has
//! typed reports of these commands, the values are built here from library calls, as the
//! command line builds them; switching to a typed report is then one line per command
//! (`serde_json::to_value(report)`).

pub mod bodies;
pub mod classify;
pub mod map;
pub mod simulate;
