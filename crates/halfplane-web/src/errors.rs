//! Errors as the page shows them: the message exactly as the command writes it after `error: `
//! (`{error:#}`, the whole chain), the form field it belongs to when the error carries one as data
//! (a library error's `field`, or the case crate's [`FieldError`], which the page's own errors
//! about a field also are), the library's kind and name,
//! and a hint chosen by [`halfplane::Error::alternative`]. Nothing here reads an error's text.

use halfplane::error::Alternative;
use halfplane::Error;
use halfplane_case::case::FieldError;
use serde::Serialize;

/// An error, for the page.
#[derive(Debug, Serialize)]
pub struct PageError {
    /// The message, as `halfplane` prints it after `error: `.
    pub message: String,
    /// The case field it concerns (`material.youngs_modulus`, `cycle.point1.normal`, `points`),
    /// when the error names one as data.
    pub field: Option<String>,
    /// `input`, `outside-analysis` or `solver` ([`halfplane::error::ErrorKind`]); `input` for errors
    /// of the case file itself.
    pub kind: &'static str,
    /// The library variant's stable name ([`Error::name`]), when it is a library error.
    pub name: Option<&'static str>,
    /// Where else to look, for errors with an [`Alternative`].
    pub hint: Option<&'static str>,
}

impl PageError {
    /// The page's view of `error`.
    pub fn new(error: &anyhow::Error) -> Self {
        let library = error.chain().find_map(|e| e.downcast_ref::<Error>());
        let field = match library {
            Some(Error::InvalidInput { field, .. } | Error::InvalidCount { field, .. }) => {
                Some(field.clone())
            }
            _ => error
                .chain()
                .find_map(|e| e.downcast_ref::<FieldError>())
                .map(|f| f.field.clone()),
        };
        Self {
            message: format!("{error:#}"),
            field,
            kind: library.map_or("input", |e| e.kind().as_str()),
            name: library.map(Error::name),
            hint: library.and_then(|e| match e.alternative()? {
                Alternative::March => Some(
                    "time marching has no such restriction: the march on this page runs the \
                     case's [history] (as `halfplane march` does)",
                ),
                _ => None,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_library_error_keeps_its_message_kind_and_name() {
        for error in halfplane::error::one_of_each() {
            let page = PageError::new(&anyhow::Error::from(error.clone()));
            assert_eq!(page.message, error.to_string());
            assert_eq!(page.kind, error.kind().as_str());
            assert_eq!(page.name, Some(error.name()));
            assert_eq!(
                page.hint.is_some(),
                error.alternative() == Some(Alternative::March),
                "{}",
                error.name()
            );
        }
    }

    #[test]
    fn a_field_is_taken_from_the_error_data_through_any_context() {
        let input = Error::InvalidInput {
            field: "friction.coefficient".into(),
            value: -1.0,
            valid: "> 0",
        };
        let wrapped = anyhow::Error::from(input).context("in case file x.toml");
        let page = PageError::new(&wrapped);
        assert_eq!(page.field.as_deref(), Some("friction.coefficient"));
        assert!(page
            .message
            .starts_with("in case file x.toml: invalid friction.coefficient"));
        let missing = anyhow::Error::from(FieldError {
            field: "profile.radius".into(),
            message: "missing field profile.radius: give R".into(),
        });
        assert_eq!(
            PageError::new(&missing).field.as_deref(),
            Some("profile.radius")
        );
        let other = anyhow::anyhow!("invalid profile.kind = \"x\"");
        assert_eq!(PageError::new(&other).field, None);
    }
}
