//! Exemplars that ship with Tracery, drawn for it (see `assets/README.md`).

use super::{Exemplar, ExemplarError, LoadOptions};

macro_rules! builtins {
    ($($name:literal),* $(,)?) => {
        /// Names of the built-in exemplars, in display order.
        pub const BUILTIN_NAMES: &[&str] = &[$($name),*];

        /// The SVG source of a built-in exemplar.
        pub fn builtin_svg(name: &str) -> Option<&'static str> {
            match name {
                $($name => Some(include_str!(concat!("../../../assets/", $name, ".svg"))),)*
                _ => None,
            }
        }
    };
}

builtins!("lace", "chain", "vine", "meander", "tilted", "filigree", "islands", "braid");

/// Loads a built-in exemplar by name.
///
/// ```
/// for name in tracery_core::vector_brush::BUILTIN_NAMES {
///     assert!(tracery_core::vector_brush::builtin(name).is_ok());
/// }
/// ```
pub fn builtin(name: &str) -> Result<Exemplar, ExemplarError> {
    let svg = builtin_svg(name).ok_or_else(|| ExemplarError::NotSvg(format!("no built-in exemplar named '{name}'")))?;
    Exemplar::from_svg_str(name, svg, &LoadOptions::default())
}
