//! The `format` field of a file read leniently (any struct name, unknown fields ignored, in RON
//! comments allowed), to tell the kinds of file apart for messages and for the listing of a
//! directory. Untrusted: the kernel reads the header of every file it checks itself, strictly.

use chatter_kernel::syntax::Encoding;

/// The `format` field of text in the given encoding, read leniently (unknown fields ignored).
pub fn format_of_in(text: &str, encoding: Encoding) -> Option<String> {
    match encoding {
        Encoding::Ron => format_of(text),
        Encoding::Json => {
            #[derive(serde::Deserialize)]
            struct Format {
                format: Option<String>,
            }
            serde_json::from_str::<Format>(text).ok().and_then(|h| h.format)
        }
    }
}

/// The `format` field of a certificate, refutation or proof file, read leniently (any struct
/// name, unknown fields ignored), to tell the kinds apart; `None` if the text is not RON with a
/// `format`.
pub fn format_of(text: &str) -> Option<String> {
    #[derive(serde::Deserialize)]
    struct Header {
        format: Option<String>,
    }
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    // The struct name in the text must match the one deserialised: try both.
    #[derive(serde::Deserialize)]
    #[serde(rename = "Certificate")]
    struct CertificateHeader {
        format: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(rename = "Proof")]
    struct ProofHeader {
        format: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(rename = "Refutation")]
    struct RefutationHeader {
        format: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(rename = "TimeToRest")]
    struct RestHeader {
        format: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(rename = "FamilyTimeToRest")]
    struct FamilyRestHeader {
        format: Option<String>,
    }
    lenient
        .from_str::<CertificateHeader>(text)
        .map(|h| h.format)
        .or_else(|_| lenient.from_str::<ProofHeader>(text).map(|h| h.format))
        .or_else(|_| lenient.from_str::<RefutationHeader>(text).map(|h| h.format))
        .or_else(|_| lenient.from_str::<RestHeader>(text).map(|h| h.format))
        .or_else(|_| lenient.from_str::<FamilyRestHeader>(text).map(|h| h.format))
        .or_else(|_| lenient.from_str::<Header>(text).map(|h| h.format))
        .ok()
        .flatten()
}
