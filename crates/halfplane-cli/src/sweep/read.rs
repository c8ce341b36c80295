//! Reading a sweep's output back (for `plot design-map`): the header, which columns are varied
//! paths (those before `regime`), and the chosen columns, numeric or text. CSV always; Parquet
//! with the `parquet` feature.

use anyhow::{anyhow, bail, Context, Result};
use halfplane_case::case::LineLimit;
use std::path::Path;

/// A column's values: numbers (absent where the cell is empty or null) or text.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// Every non-empty cell is a number.
    Number(Vec<Option<f64>>),
    /// Some cell is not a number.
    Text(Vec<String>),
}

/// The columns read from a sweep's output.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepTable {
    /// Every column name, in order.
    pub names: Vec<String>,
    /// The varied paths: the columns before `regime`.
    pub varied: Vec<String>,
    /// The columns asked for, in the order asked.
    pub columns: Vec<Values>,
    /// The number of rows.
    pub rows: usize,
}

/// Reads the columns `wanted` of a sweep output (`.csv` or `.parquet`).
pub fn read(path: &Path, wanted: &[&str]) -> Result<SweepTable> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        #[cfg(feature = "parquet")]
        Some("parquet") => parquet(path, wanted),
        #[cfg(not(feature = "parquet"))]
        Some("parquet") => bail!(
            "cannot read {}: this halfplane was built without Parquet support (--no-default-features); build it with --features parquet, or give the sweep's .csv",
            path.display()
        ),
        _ => csv(path, wanted),
    }
}

fn positions(path: &Path, names: &[String], wanted: &[&str]) -> Result<Vec<usize>> {
    let varied = varied(names);
    wanted
        .iter()
        .map(|w| {
            names.iter().position(|n| n == w).ok_or_else(|| {
                anyhow!(
                    "{} has no column {w:?}: its varied paths are {}, and its other columns {}",
                    path.display(),
                    varied.join(", "),
                    names[varied.len()..].join(", ")
                )
            })
        })
        .collect()
}

fn varied(names: &[String]) -> Vec<String> {
    names
        .iter()
        .take_while(|n| n.as_str() != "regime")
        .cloned()
        .collect()
}

fn csv(path: &Path, wanted: &[&str]) -> Result<SweepTable> {
    let file =
        std::fs::File::open(path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut reader = ::csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(LineLimit::new(file, "a sweep's output"));
    let names: Vec<String> = reader
        .headers()
        .with_context(|| format!("cannot read the header of {}", path.display()))?
        .iter()
        .map(|s| s.trim_start_matches('\u{feff}').to_string())
        .collect();
    if !names.iter().any(|n| n == "regime") {
        bail!(
            "{} is not a sweep's output: it has no regime column (a sweep writes the varied paths, then regime, ...)",
            path.display()
        );
    }
    let at = positions(path, &names, wanted)?;
    let mut raw: Vec<Vec<String>> = vec![Vec::new(); wanted.len()];
    for (i, record) in reader.records().enumerate() {
        let record =
            record.with_context(|| format!("cannot read {}, row {}", path.display(), i + 1))?;
        for (k, &j) in at.iter().enumerate() {
            raw[k].push(record.get(j).unwrap_or("").to_string());
        }
    }
    let rows = raw.first().map_or(0, Vec::len);
    let columns = raw
        .into_iter()
        .map(|cells| {
            let numbers: Option<Vec<Option<f64>>> = cells
                .iter()
                .map(|c| match c.trim() {
                    "" => Some(None),
                    t => t.parse::<f64>().ok().map(Some),
                })
                .collect();
            match numbers {
                Some(n) => Values::Number(n),
                None => Values::Text(cells),
            }
        })
        .collect();
    Ok(SweepTable {
        varied: varied(&names),
        names,
        columns,
        rows,
    })
}

#[cfg(feature = "parquet")]
fn parquet(path: &Path, wanted: &[&str]) -> Result<SweepTable> {
    use arrow_array::cast::AsArray;
    use arrow_array::types::{Float64Type, UInt64Type};
    use arrow_schema::DataType;
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
    let file =
        std::fs::File::open(path).with_context(|| format!("cannot read {}", path.display()))?;
    let builder = ParquetRecordBatchReaderBuilder::try_new(file)
        .map_err(|e| anyhow!("cannot read {} as Parquet: {e}", path.display()))?;
    let names: Vec<String> = builder
        .schema()
        .fields()
        .iter()
        .map(|f| f.name().clone())
        .collect();
    let at = positions(path, &names, wanted)?;
    let reader = builder
        .build()
        .map_err(|e| anyhow!("cannot read {}: {e}", path.display()))?;
    let mut columns: Vec<Values> = at.iter().map(|_| Values::Number(Vec::new())).collect();
    let mut rows = 0;
    for batch in reader {
        let batch = batch.map_err(|e| anyhow!("cannot read {}: {e}", path.display()))?;
        rows += batch.num_rows();
        for (k, &j) in at.iter().enumerate() {
            let array = batch.column(j);
            match array.data_type() {
                DataType::Float64 | DataType::UInt64 => {
                    let numbers: Vec<Option<f64>> = match array.data_type() {
                        DataType::Float64 => array.as_primitive::<Float64Type>().iter().collect(),
                        _ => array
                            .as_primitive::<UInt64Type>()
                            .iter()
                            .map(|v| v.map(|v| v as f64))
                            .collect(),
                    };
                    match &mut columns[k] {
                        Values::Number(v) => v.extend(numbers),
                        Values::Text(_) => {
                            bail!("{}: column {} changes type", path.display(), names[j])
                        }
                    }
                }
                // A Boolean (steady_converged) reads as the CSV's words do.
                DataType::Utf8 | DataType::Boolean => {
                    let text: Vec<String> = match array.data_type() {
                        DataType::Boolean => array
                            .as_boolean()
                            .iter()
                            .map(|b| b.map_or(String::new(), |b| b.to_string()))
                            .collect(),
                        _ => array
                            .as_string::<i32>()
                            .iter()
                            .map(|s| s.unwrap_or("").to_string())
                            .collect(),
                    };
                    match &mut columns[k] {
                        Values::Text(v) => v.extend(text),
                        Values::Number(v) if v.is_empty() => columns[k] = Values::Text(text),
                        Values::Number(_) => {
                            bail!("{}: column {} changes type", path.display(), names[j])
                        }
                    }
                }
                other => bail!(
                    "{}: column {} has type {other}, not one a sweep writes",
                    path.display(),
                    names[j]
                ),
            }
        }
    }
    Ok(SweepTable {
        varied: varied(&names),
        names,
        columns,
        rows,
    })
}
