//! The dicts of `classify`, `simulate`, `bodies` and `map`: each is the library's typed report
//! (`chatter::report`, docs/json.md) as a `serde_json::Value` (`report::to_value`), made by one
//! function per command (`value`) after checking the arguments as the command line does. `map`
//! adds the points as columns (`"columns"`) to its summary.

pub mod bodies;
pub mod classify;
pub mod map;
pub mod simulate;
