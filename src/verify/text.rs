//! Verification of certificate text held in memory (the Python package's `verify(text)`): the
//! rules of [`super::verify_file`] without the file, with the text's size checked against
//! `max-file-size`.

use super::{FileVerdict, Kind, Options, Status, out_of_time, too_large, verify_any, with_time_limit};
use chatter_kernel::certificate::Encoding;
use chatter_kernel::exact::ParseLimits;
use std::path::Path;

/// The name under which a verdict on text is reported.
pub const TEXT_PATH: &str = "<text>";

/// Verifies certificate or refutation text (RON or its JSON twin) on the backends of `opts`,
/// under its limits; the verdict's path is [`TEXT_PATH`].
pub fn verify_text(text: &str, encoding: Encoding, opts: &Options) -> FileVerdict {
    let path = Path::new(TEXT_PATH);
    if text.len() as u64 > opts.max_file_size {
        return too_large(path, &format!("the text has {} bytes", text.len()), opts.max_file_size);
    }
    let (text, limits, backends) = (text.to_string(), opts.limits, opts.backends.clone());
    let run = move |deadline| verify_any(&text, encoding, ParseLimits { deadline, ..limits }, &backends);
    let Some((mut v, kind)) = with_time_limit(opts.time_limit, run) else {
        return out_of_time(path, opts.time_limit.unwrap_or_default());
    };
    v.path = TEXT_PATH.to_string();
    if kind == Kind::Proof && v.status == Status::Rejected {
        v.reason = v.reason.map(|r| format!("{r} (this text is a proof: use `chatter check-proof`)"));
    }
    v
}
