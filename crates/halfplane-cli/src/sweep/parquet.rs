//! Parquet output of a sweep (the `parquet` feature): the same columns as the CSV, typed. The
//! varied paths and the numbers are `Float64`, `regime`, `error` and `crack.verdict` are `Utf8`,
//! `shakedown_cycle`, `cycles_run` and `wear.simulated_cycles` are `UInt64`, `steady_converged` is `Boolean`; a value the row does not have is null (never NaN), and `error`
//! is null when the row succeeded. Each chunk of rows is written as it arrives; row groups hold
//! at most [`ROW_GROUP_ROWS`] rows, so memory stays bounded whatever the sweep's length.

use super::spec::Analysis;
use super::template::Outcome;
use super::{csv::part_path, Layout, RowSink};
use anyhow::{anyhow, Context, Result};
use arrow_array::builder::{BooleanBuilder, Float64Builder, StringBuilder, UInt64Builder};
use arrow_array::{ArrayRef, RecordBatch};
use arrow_schema::{DataType, Field, Schema, SchemaRef};
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::properties::WriterProperties;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The most rows in one row group.
pub const ROW_GROUP_ROWS: usize = 65_536;

/// One row, as the workers hand it over.
#[derive(Debug, Clone)]
pub struct ParquetRow {
    values: Vec<f64>,
    outcome: Outcome,
}

/// Writes a sweep's rows to `PATH.part`, renamed to `PATH` when the sweep completes.
pub struct ParquetSink {
    writer: ArrowWriter<File>,
    schema: SchemaRef,
    layout: Layout,
    part: PathBuf,
    path: PathBuf,
}

/// The schema of a sweep's rows.
pub fn schema(layout: &Layout) -> Schema {
    let mut fields: Vec<Field> = layout
        .varied
        .iter()
        .map(|v| Field::new(&v.path, DataType::Float64, false))
        .collect();
    for name in &layout.columns()[layout.varied.len()..] {
        let kind = match name.as_str() {
            "regime" | "error" | "crack.verdict" => DataType::Utf8,
            "shakedown_cycle" | "cycles_run" | "wear.simulated_cycles" => DataType::UInt64,
            "steady_converged" => DataType::Boolean,
            _ => DataType::Float64,
        };
        fields.push(Field::new(name, kind, true));
    }
    Schema::new(fields)
}

/// One number per row, null where `value` gives none or a value that is not finite (the CSV's
/// empty cell).
fn finite_column(rows: &[ParquetRow], value: impl Fn(&Outcome) -> Option<f64>) -> ArrayRef {
    let mut b = Float64Builder::with_capacity(rows.len());
    for r in rows {
        b.append_option(value(&r.outcome).filter(|v| v.is_finite()));
    }
    Arc::new(b.finish())
}

impl ParquetSink {
    /// Creates the output (Snappy-compressed).
    pub fn create(path: &Path, layout: &Layout) -> Result<Self> {
        let part = part_path(path);
        let file =
            File::create(&part).with_context(|| format!("cannot create {}", part.display()))?;
        let schema = Arc::new(schema(layout));
        let props = WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .set_max_row_group_row_count(Some(ROW_GROUP_ROWS))
            .build();
        let writer = ArrowWriter::try_new(file, schema.clone(), Some(props))
            .map_err(|e| anyhow!("cannot write {}: {e}", part.display()))?;
        Ok(Self {
            writer,
            schema,
            layout: layout.clone(),
            part,
            path: path.to_path_buf(),
        })
    }

    fn batch(&self, rows: &[ParquetRow]) -> Result<RecordBatch> {
        let n = rows.len();
        let mut columns: Vec<ArrayRef> = Vec::new();
        for j in 0..self.layout.varied.len() {
            let mut b = Float64Builder::with_capacity(n);
            rows.iter().for_each(|r| b.append_value(r.values[j]));
            columns.push(Arc::new(b.finish()));
        }
        let mut regime = StringBuilder::new();
        for r in rows {
            regime.append_option(r.outcome.steady.map(|s| s.regime().as_str()));
        }
        columns.push(Arc::new(regime.finish()));
        for k in 0..halfplane::batch::STEADY_NUMBERS {
            columns.push(finite_column(rows, |o| o.steady.map(|s| s.numbers()[k])));
        }
        let mut error = StringBuilder::new();
        for r in rows {
            error.append_option(Some(r.outcome.error.as_str()).filter(|e| !e.is_empty()));
        }
        columns.push(Arc::new(error.finish()));
        if self.layout.analysis == Analysis::March {
            let march = |f: &dyn Fn(&halfplane::batch::MarchSummary) -> Option<f64>| {
                let mut b = Float64Builder::with_capacity(n);
                for r in rows {
                    b.append_option(r.outcome.march.as_ref().and_then(f));
                }
                Arc::new(b.finish()) as ArrayRef
            };
            columns.push(march(&|m| m.energy()));
            columns.push(march(&|m| m.max_slip_amplitude()));
            let mut shakedown = UInt64Builder::with_capacity(n);
            for r in rows {
                shakedown.append_option(
                    r.outcome
                        .march
                        .and_then(|m| m.shakedown_cycle())
                        .map(|k| k as u64),
                );
            }
            columns.push(Arc::new(shakedown.finish()));
            columns.push(march(&|m| m.final_stick().map(|z| z[0])));
            columns.push(march(&|m| m.final_stick().map(|z| z[1])));
            let mut cycles_run = UInt64Builder::with_capacity(n);
            let mut converged = BooleanBuilder::with_capacity(n);
            for r in rows {
                let m = r.outcome.march.as_ref();
                cycles_run.append_option(m.map(|m| m.cycles_run() as u64));
                converged.append_option(m.and_then(|m| m.steady_converged()));
            }
            columns.push(Arc::new(cycles_run.finish()));
            columns.push(march(&|m| m.steady_change()));
            columns.push(Arc::new(converged.finish()));
        }
        if self.layout.analysis == Analysis::Crack {
            let mut verdict = StringBuilder::new();
            let mut arrest = Float64Builder::with_capacity(n);
            for r in rows {
                let c = r.outcome.crack.as_ref();
                verdict.append_option(c.map(|c| c.verdict.name()));
                arrest.append_option(c.and_then(|c| c.arrest_length));
            }
            columns.push(Arc::new(verdict.finish()));
            columns.push(Arc::new(arrest.finish()));
        }
        if self.layout.analysis == Analysis::Wear {
            // Every wear column but the last, the cycles marched.
            for k in 0..super::WEAR_COLUMNS.len() - 1 {
                columns.push(finite_column(rows, |o| o.wear.and_then(|w| w.numbers()[k])));
            }
            let mut simulated = UInt64Builder::with_capacity(n);
            for r in rows {
                simulated.append_option(r.outcome.wear.map(|w| w.simulated_cycles as u64));
            }
            columns.push(Arc::new(simulated.finish()));
        }
        RecordBatch::try_new(self.schema.clone(), columns)
            .map_err(|e| anyhow!("cannot assemble the rows for {}: {e}", self.part.display()))
    }
}

impl RowSink for ParquetSink {
    type Item = ParquetRow;

    fn encode(_: &Layout, values: &[f64], outcome: Outcome) -> ParquetRow {
        ParquetRow {
            values: values.to_vec(),
            outcome,
        }
    }

    fn write(&mut self, rows: Vec<ParquetRow>) -> Result<()> {
        let batch = self.batch(&rows)?;
        self.writer
            .write(&batch)
            .map_err(|e| anyhow!("cannot write {}: {e}", self.part.display()))
    }

    fn finish(self) -> Result<()> {
        let Self {
            writer, part, path, ..
        } = self;
        writer
            .close()
            .map_err(|e| anyhow!("cannot write {}: {e}", part.display()))?;
        std::fs::rename(&part, &path)
            .with_context(|| format!("cannot rename {} to {}", part.display(), path.display()))
    }
}
