//! Which flag a refused setting came from: core names the settings field
//! (`thickness_mm`), the command line names the flag (`--thickness`), so
//! that a refusal says what to change.

use clap::CommandFactory as _;
use tracery_core::setting::InvalidSetting;

use super::Cli;

/// Settings fields whose flag is not the field's name less its unit.
const RENAMED: &[(&str, &str)] = &[("delta_mm", "spacing")];

/// The flag of `subcommand` that sets `field`, if it has one.
pub fn flag_for(subcommand: &str, field: &str) -> Option<String> {
    let command = Cli::command();
    let sub = command.find_subcommand(subcommand)?;
    let renamed = RENAMED.iter().find(|(f, _)| *f == field).map(|(_, flag)| flag.to_string());
    let plain = field.trim_end_matches("_mm").trim_end_matches("_deg").replace('_', "-");
    let whole = field.replace('_', "-");
    [renamed, Some(plain), Some(whole)]
        .into_iter()
        .flatten()
        .find(|name| sub.get_arguments().any(|a| a.get_long() == Some(name.as_str())))
        .map(|name| format!("--{name}"))
}

/// A refused setting as an error that starts with its flag.
pub fn flagged(subcommand: &str, e: InvalidSetting) -> anyhow::Error {
    match flag_for(subcommand, e.field) {
        Some(flag) => anyhow::anyhow!("{flag}: {e}"),
        None => anyhow::Error::new(e),
    }
}

/// `result` with a refused setting named by its flag.
pub fn check(subcommand: &str, result: Result<(), InvalidSetting>) -> anyhow::Result<()> {
    result.map_err(|e| flagged(subcommand, e))
}
