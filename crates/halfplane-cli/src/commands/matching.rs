//! `halfplane match`: the test loads that reproduce a prototype's contact-edge state, written as
//! a complete test case (docs/matching.md). The computation is `halfplane_case::matching`; this
//! module reads the prototype and writes the files and the report.

use crate::args::MatchArgs;
use crate::output::{emit, note};
use anyhow::{Context, Result};
use halfplane_case::matching::{compute, MatchConfig};
use halfplane_case::report::matching::MatchReportOut;

/// Reads the prototype (it must have a `[cycle]`) and builds the test contact from the options,
/// the prototype's material and friction where they are not given.
pub fn resolve(args: &MatchArgs) -> Result<MatchConfig> {
    let prototype = crate::case::load(&args.case)?;
    let text = halfplane_case::case::read_text(&args.case, "case file")?;
    MatchConfig::from_case(
        prototype,
        &text,
        args.case.clone(),
        &args.test.options(),
        args.output.clone(),
    )
}

/// Finds the test, writes the test case and prints the report (`json`: as one JSON object);
/// warnings go to stderr unless the JSON carries them.
pub fn run(config: &MatchConfig, json: bool) -> Result<()> {
    let matched = compute(config)?;
    if let Some((path, csv)) = &matched.history_csv {
        std::fs::write(path, csv).with_context(|| format!("cannot write {}", path.display()))?;
    }
    std::fs::write(&config.output, &matched.test_case)
        .with_context(|| format!("cannot write {}", config.output.display()))?;
    let out = MatchReportOut::new(&matched.report, config, &matched.notes);
    emit(&if json {
        out.json()? + "\n"
    } else {
        out.table()
    })?;
    if !json {
        for n in &matched.notes {
            note(n);
        }
    }
    note(&format!("wrote {}", config.output.display()));
    Ok(())
}
