//! The `steady` report as one CSV row: [`SteadyReport::COLUMNS`], the JSON's values under their
//! dotted paths.

use super::SteadyReport;

impl SteadyReport {
    /// The one-row CSV's columns: every number and name of the JSON under its dotted path,
    /// always all of them and in this order, so rows of different cases
    /// line up; a value the case does not have (a profile parameter of another kind, the stick
    /// zone when sliding, the asymptotics outside partial slip) is an empty cell. `profile.kinks`
    /// lists the kinks space-separated.
    pub const COLUMNS: [&'static str; 82] = [
        "regime",
        "profile.kind",
        "profile.radius",
        "profile.flat_half_width",
        "profile.coefficient",
        "profile.exponent",
        "profile.rows",
        "profile.kinks",
        "compliance",
        "friction",
        "points.at_point1.normal",
        "points.at_point1.shear",
        "points.at_point1.bulk",
        "points.at_point2.normal",
        "points.at_point2.shear",
        "points.at_point2.bulk",
        "smaller_shear_point",
        "criteria.shear_ratio_1",
        "criteria.shear_ratio_2",
        "criteria.full_stick_ratio",
        "criteria.shear_range",
        "criteria.bulk_term",
        "criteria.friction",
        "contact.half_width_1",
        "contact.half_width_2",
        "contact.normal_intensity_1",
        "contact.normal_intensity_2",
        "stick_zone.left",
        "stick_zone.right",
        "stick_zone.half_width",
        "stick_zone.eccentricity",
        "slip_zones.left.at_point1",
        "slip_zones.left.at_point2",
        "slip_zones.right.at_point1",
        "slip_zones.right.at_point2",
        "asymptotic.stick_zone.left",
        "asymptotic.stick_zone.right",
        "asymptotic.stick_zone.relative_difference_left",
        "asymptotic.stick_zone.relative_difference_right",
        "asymptotic.stick_load.left",
        "asymptotic.stick_load.right",
        "asymptotic.edges.at_point1.shear_intensity_left",
        "asymptotic.edges.at_point1.shear_intensity_right",
        "asymptotic.edges.at_point1.equivalent_shear_left",
        "asymptotic.edges.at_point1.equivalent_shear_right",
        "asymptotic.edges.at_point2.shear_intensity_left",
        "asymptotic.edges.at_point2.shear_intensity_right",
        "asymptotic.edges.at_point2.equivalent_shear_left",
        "asymptotic.edges.at_point2.equivalent_shear_right",
        "asymptotic.slip_zones.left.at_point1.estimate",
        "asymptotic.slip_zones.left.at_point1.exact",
        "asymptotic.slip_zones.left.at_point1.relative_difference",
        "asymptotic.slip_zones.left.at_point2.estimate",
        "asymptotic.slip_zones.left.at_point2.exact",
        "asymptotic.slip_zones.left.at_point2.relative_difference",
        "asymptotic.slip_zones.right.at_point1.estimate",
        "asymptotic.slip_zones.right.at_point1.exact",
        "asymptotic.slip_zones.right.at_point1.relative_difference",
        "asymptotic.slip_zones.right.at_point2.estimate",
        "asymptotic.slip_zones.right.at_point2.exact",
        "asymptotic.slip_zones.right.at_point2.relative_difference",
        "units.force",
        "units.length",
        "units.stress",
        "profile.left_radius",
        "profile.right_radius",
        "points.at_point1.moment",
        "points.at_point2.moment",
        "contact.left_1",
        "contact.right_1",
        "contact.left_2",
        "contact.right_2",
        "contact.normal_intensity_left_1",
        "contact.normal_intensity_right_1",
        "contact.normal_intensity_left_2",
        "contact.normal_intensity_right_2",
        "contact.rotation_1",
        "contact.rotation_2",
        "contact.on_flat_left_1",
        "contact.on_flat_right_1",
        "contact.on_flat_left_2",
        "contact.on_flat_right_2",
    ];

    /// A header of [`Self::COLUMNS`] and one row: each the JSON value at that path, numbers as
    /// Rust writes them (as the other commands' CSV), empty when absent or null.
    pub fn csv(&self) -> serde_json::Result<String> {
        let v = serde_json::to_value(self)?;
        let cell = |path: &str| -> String {
            let found = path.split('.').try_fold(&v, |v, key| v.get(key));
            match found {
                Some(serde_json::Value::Number(n)) => match (n.as_u64(), n.as_f64()) {
                    (Some(i), _) => i.to_string(),
                    (None, Some(x)) => x.to_string(),
                    (None, None) => n.to_string(),
                },
                Some(serde_json::Value::String(s)) => s.clone(),
                Some(serde_json::Value::Bool(b)) => b.to_string(),
                Some(serde_json::Value::Array(a)) => a
                    .iter()
                    .map(|x| x.as_f64().map_or_else(String::new, |x| x.to_string()))
                    .collect::<Vec<_>>()
                    .join(" "),
                _ => String::new(),
            }
        };
        let row: Vec<String> = Self::COLUMNS.iter().map(|c| cell(c)).collect();
        Ok(format!("{}\n{}\n", Self::COLUMNS.join(","), row.join(",")))
    }
}
