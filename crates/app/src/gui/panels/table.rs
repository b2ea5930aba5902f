//! The Mass properties section: the exact tensor's moments beside the bounding box's and the
//! point masses' (errors and axis angles), and which inertia the simulation uses.

use massprops::MassProperties;

use egui::{Color32, RichText};

use super::{Frame, Panel, restart_on_switch};
use crate::i18n::{fixed, localize, sci, tr};
use crate::lab::Lab;
use crate::lab::settings::{AppSettings, InertiaSource};

/// The Mass properties section: the table of every source and the inertia the simulation uses.
pub struct TableSection;

impl Panel for TableSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        table_section(ui, f.lab, f.settings);
    }
}

fn fmt(x: f64) -> String {
    sci(x, 4)
}

fn table_section(ui: &mut egui::Ui, lab: &Lab, s: &mut AppSettings) {
    egui::CollapsingHeader::new(tr!("table-header"))
        .id_salt("mass-properties")
        .default_open(true)
        .show(ui, |ui| {
            let primary = lab.primary();
            let sources = shown_sources(primary);
            let exact = primary.properties(InertiaSource::Exact);
            let others: Vec<(&MassProperties, massprops::properties::Comparison)> = sources[1..]
                .iter()
                .map(|&src| (primary.properties(src), primary.comparison(src)))
                .collect();
            egui::Grid::new("mass-table")
                .striped(true)
                .num_columns(sources.len() + 1)
                .show(ui, |ui| {
                    ui.label("");
                    for src in &sources {
                        ui.strong(column_label(*src))
                            .on_hover_text(source_meaning(*src));
                    }
                    ui.end_row();
                    ui.label(tr!("table-mass"));
                    ui.label(fmt(exact.mass));
                    for (p, _) in &others {
                        ui.label(if p.mass == exact.mass {
                            tr!("table-same")
                        } else {
                            fmt(p.mass)
                        });
                    }
                    ui.end_row();
                    for i in 0..3 {
                        ui.label(format!("I{} (kg·m²)", i + 1))
                            .on_hover_text(tr!("table-moment-hover", axis = i + 1));
                        ui.label(fmt(exact.principal.moments[i]));
                        for (p, _) in &others {
                            ui.label(fmt(p.principal.moments[i]));
                        }
                        ui.end_row();
                    }
                    for i in 0..3 {
                        ui.label(tr!("table-error", axis = i + 1))
                            .on_hover_text(tr!("table-error-hover", axis = i + 1));
                        ui.label("—");
                        for (_, c) in &others {
                            let e = c.moment_error[i] * 100.0;
                            ui.label(error_text(localize(format!("{e:+.1} %")), e.abs() > 5.0));
                        }
                        ui.end_row();
                    }
                    for i in 0..3 {
                        ui.label(tr!("table-axis-angle", axis = i + 1))
                            .on_hover_text(tr!("table-axis-angle-hover", axis = i + 1));
                        ui.label("—");
                        for (_, c) in &others {
                            match c.axis_angle[i] {
                                Some(a) => {
                                    let deg = a.to_degrees();
                                    ui.label(error_text(format!("{}°", fixed(deg, 1)), deg > 5.0))
                                }
                                None => ui.label(tr!("table-not-applicable")),
                            };
                        }
                        ui.end_row();
                    }
                    ui.label(tr!("table-com-offset"))
                        .on_hover_text(tr!("table-com-offset-hover"));
                    ui.label("—");
                    for (_, c) in &others {
                        ui.label(fmt(c.com_offset));
                    }
                    ui.end_row();
                });
            // A coordinate below 1e-12 of the body's size is round-off of a zero (as in the
            // command line's table): shown as 0, not as -5.3e-19.
            let size = primary.bounding_sphere().1;
            let c = exact
                .center_of_mass
                .map(|x| if x.abs() < 1e-12 * size { 0.0 } else { x });
            ui.add(
                egui::Label::new(
                    RichText::new(tr!(
                        "table-center-of-mass",
                        x = sci(c.x, 3),
                        y = sci(c.y, 3),
                        z = sci(c.z, 3),
                    ))
                    .small(),
                )
                .wrap(),
            );
            ui.label(RichText::new(tr!("table-simulation-uses")).strong());
            ui.horizontal(|ui| {
                for src in sources {
                    ui.radio_value(&mut s.body.source, src, src.label())
                        .on_hover_text(source_meaning(src));
                }
            });
            restart_on_switch(ui, s);
        });
}

/// An inertia source's column header: the long names shortened, so that the table fits.
fn column_label(source: InertiaSource) -> String {
    match source {
        InertiaSource::BoundingBox => tr!("table-column-bbox"),
        InertiaSource::PointMasses => tr!("table-column-points"),
        InertiaSource::Exact | InertiaSource::Stated => source.label(),
    }
}

/// What each inertia source is, for the table's headers and the radio buttons.
fn source_meaning(source: InertiaSource) -> String {
    match source {
        InertiaSource::Exact => tr!("table-meaning-exact"),
        InertiaSource::BoundingBox => tr!("table-meaning-bounding-box"),
        InertiaSource::PointMasses => tr!("table-meaning-point-masses"),
        InertiaSource::Stated => tr!("table-meaning-stated"),
    }
}

/// The sources the body has: the stated one only for a robot link that states an inertia.
fn shown_sources(primary: &crate::lab::Specimen) -> Vec<InertiaSource> {
    InertiaSource::ALL
        .into_iter()
        .filter(|&s| s != InertiaSource::Stated || primary.body().stated.is_some())
        .collect()
}

fn error_text(text: String, large: bool) -> RichText {
    if large {
        RichText::new(text).color(Color32::from_rgb(255, 140, 90))
    } else {
        RichText::new(text)
    }
}
