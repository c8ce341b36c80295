//! A case file's text as the form's fields: every value under its dotted name
//! (`material.youngs_modulus`, `cycle.point1.normal`, `profile.data`), so that the page fills its
//! form from a `#case=` link whatever fields the form has (a field it lacks is listed by the page
//! as not shown). Numbers are written as TOML reads them back exactly (Rust's shortest
//! round-trip form), lists of numbers space-separated, strings as they are.

use anyhow::{anyhow, Result};
use serde_json::{Map, Value};

/// The fields of case text, by dotted name.
pub fn fields(text: &str) -> Result<Value> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let doc: toml::Table =
        toml::from_str(text).map_err(|e| anyhow!("{}", e.to_string().trim_end()))?;
    let mut out = Map::new();
    flatten("", &doc, &mut out);
    Ok(Value::Object(out))
}

/// The sections of case text other than `owned` (comma-separated names: those the form writes
/// itself), as TOML text to append to the form's: a linked case keeps what the form does not
/// show (`[fatigue]`, `[crack]`, a harmonic `[history]`), so that its download is the whole case.
pub fn other_sections(text: &str, owned: &str) -> Result<Value> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut doc: toml::Table =
        toml::from_str(text).map_err(|e| anyhow!("{}", e.to_string().trim_end()))?;
    for name in owned.split(',') {
        doc.remove(name.trim());
    }
    Ok(Value::String(toml::to_string(&doc)?))
}

fn flatten(prefix: &str, table: &toml::Table, out: &mut Map<String, Value>) {
    for (key, value) in table {
        let name = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        match value {
            toml::Value::Table(t) => flatten(&name, t, out),
            other => {
                out.insert(name, Value::String(written(other)));
            }
        }
    }
}

/// A value as the form shows it.
fn written(value: &toml::Value) -> String {
    match value {
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(x) => format!("{x:?}"),
        toml::Value::Array(items) => items.iter().map(written).collect::<Vec<_>>().join(" "),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_value_is_named_by_its_path() {
        let text = "[material]\nyoungs_modulus = 2e5\n[profile]\nkind = \"tabulated\"\n\
                    data = \"\"\"x,g\n0,0\n\"\"\"\nkinks = [0.3, 1]\n\
                    [cycle]\npoint1 = { normal = 1000.0, shear = -250 }\n";
        let v = fields(text).unwrap();
        assert_eq!(v["material.youngs_modulus"], "200000.0");
        assert_eq!(v["profile.kind"], "tabulated");
        assert_eq!(v["profile.data"], "x,g\n0,0\n");
        assert_eq!(v["profile.kinks"], "0.3 1");
        assert_eq!(v["cycle.point1.normal"], "1000.0");
        assert_eq!(v["cycle.point1.shear"], "-250");
        assert!(fields("[material").is_err());
    }

    #[test]
    fn the_sections_the_form_does_not_write_are_kept_whole() {
        let text = "[material]\nyoungs_modulus = 1.0\n[fatigue]\nk = 0.5\n[crack.faces]\nf = 0.1\n";
        let v = other_sections(text, "material, cycle").unwrap();
        let kept: toml::Table = toml::from_str(v.as_str().unwrap()).unwrap();
        let mut names: Vec<&String> = kept.keys().collect();
        names.sort();
        assert_eq!(names, ["crack", "fatigue"]);
        assert_eq!(kept["crack"]["faces"]["f"].as_float(), Some(0.1));
    }

    #[test]
    fn a_number_is_written_so_that_it_reads_back_exactly() {
        for x in [0.1_f64 + 0.2, 1e-300, -2.5e21, 1.0 / 3.0] {
            let v = fields(&format!("x = {x:?}")).unwrap();
            let back: f64 = v["x"].as_str().unwrap().parse().unwrap();
            assert_eq!(back.to_bits(), x.to_bits());
        }
    }
}
