//! The plot panel: ω in the principal frame, L in world with |L|, and the energies, side by side
//! with linked time axes over a sliding window; the energy drift as a number; CSV export.

use std::path::PathBuf;

use egui::Color32;
use egui_plot::{GridMark, HoverPosition, Legend, Line, LineStyle, Plot, PlotPoints};

use super::{Frame, Panel, PanelState, localized, number};
use crate::gui::platform::{self, DialogPurpose};
use crate::gui::view3d::overlay::AXIS_COLORS;
use crate::i18n::{fixed, localize, sci, tr};
use crate::lab::history::History;
use crate::lab::settings::AppSettings;
use crate::lab::{Command, Lab, PRIMARY};
use crate::timeseries::Sample;

type Series = (&'static str, Color32, fn(&Sample) -> f64);

const OMEGA: [Series; 3] = [
    ("ω1", AXIS_COLORS[0], |s| s.omega_principal[0]),
    ("ω2", AXIS_COLORS[1], |s| s.omega_principal[1]),
    ("ω3", AXIS_COLORS[2], |s| s.omega_principal[2]),
];
const MOMENTUM: [Series; 4] = [
    ("Lx", AXIS_COLORS[0], |s| s.l[0]),
    ("Ly", AXIS_COLORS[1], |s| s.l[1]),
    ("Lz", AXIS_COLORS[2], |s| s.l[2]),
    ("|L|", Color32::WHITE, |s| s.l_norm),
];
const ENERGY: [Series; 3] = [
    ("T", Color32::from_rgb(255, 170, 60), |s| s.kinetic),
    ("U", Color32::from_rgb(110, 200, 255), |s| s.potential),
    ("E", Color32::WHITE, |s| s.energy),
];

/// The plot panel, with what it alone keeps: whether it follows the latest time, and where
/// "Export CSV" writes.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotsPanel {
    /// Whether the plots follow the latest time (sliding window) or stay where the user put them.
    pub follow: bool,
    /// Where "Export CSV" writes.
    pub csv_path: String,
}

impl Default for PlotsPanel {
    fn default() -> Self {
        Self {
            follow: true,
            csv_path: "inertia-lab.csv".to_owned(),
        }
    }
}

impl Panel for PlotsPanel {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui, f.lab, f.settings, self, f.shared, f.commands);
    }
}

/// Shows the controls row and the three plots.
fn show(
    ui: &mut egui::Ui,
    lab: &Lab,
    settings: &mut AppSettings,
    own: &mut PlotsPanel,
    state: &mut PanelState,
    commands: &mut Vec<Command>,
) {
    let history = lab.primary().history();
    // Wraps within the plot panel in a narrow window: every control stays reachable.
    ui.horizontal_wrapped(|ui| {
        super::pause_button(ui, lab, commands);
        ui.checkbox(&mut own.follow, tr!("plots-follow"));
        number(
            ui,
            &tr!("plots-window"),
            &mut settings.plots.window,
            0.5..=600.0,
            0.5,
            " s",
        );
        number(
            ui,
            &tr!("plots-history"),
            &mut settings.plots.history,
            1.0..=600.0,
            1.0,
            " s",
        );
        ui.separator();
        ui.label(drift_text(lab));
        let dropped = lab.primary().dropped();
        // Shown from 5 ms on: the label says hundredths of a second.
        if dropped >= 0.005 {
            ui.colored_label(
                Color32::from_rgb(255, 170, 60),
                tr!("plots-skipped", seconds = fixed(dropped, 2)),
            )
            .on_hover_text(tr!("plots-skipped-hover"));
        }
        ui.separator();
        let l = ui.label(tr!("plots-csv"));
        ui.add(egui::TextEdit::singleline(&mut own.csv_path).desired_width(120.0))
            .labelled_by(l.id);
        if ui.button(tr!("plots-export-csv")).clicked() && !own.csv_path.trim().is_empty() {
            commands.push(Command::ExportCsv {
                specimen: PRIMARY,
                path: PathBuf::from(own.csv_path.trim()),
            });
        }
        if ui
            .add_enabled(!state.dialog_open, egui::Button::new("…"))
            .on_hover_text(tr!("plots-choose-file-hover"))
            .clicked()
        {
            state.dialog_request = Some(DialogPurpose::SaveCsv);
        }
        ui.separator();
        match state.recording {
            Some(left) => {
                ui.label(tr!("plots-recording", seconds = fixed(left, 1)));
                if ui.button(tr!("plots-stop")).clicked() {
                    state.record_stop = true;
                }
            }
            None => {
                if ui
                    .button(tr!("plots-record"))
                    .on_hover_text(platform::record_hint())
                    .clicked()
                {
                    state.record_request = true;
                }
                ui.add(
                    localized(egui::DragValue::new(&mut state.record_seconds))
                        .range(0.5..=120.0)
                        .speed(0.5)
                        .suffix(" s"),
                )
                .on_hover_text(tr!("plots-record-seconds-hover"));
            }
        }
    });
    let t_end = history.last().map_or(0.0, |s| s.t);
    let window = settings.plots.window;
    // Until a full window has elapsed the axis shows [0, window] rather than negative time.
    let bounds = own
        .follow
        .then_some(((t_end - window).max(0.0), t_end.max(window)));
    let since = bounds.map_or(f64::NEG_INFINITY, |b| b.0);
    let gap = ui.spacing().item_spacing.x;
    let width = ((ui.available_width() - 2.0 * gap) / 3.0).max(50.0);
    let height = (ui.available_height() - 20.0).max(60.0);
    // Compared copies add their ω curves, dashed, in the same colour per axis.
    let copies: Vec<&History> = lab.specimens()[1..].iter().map(|s| s.history()).collect();
    let lines = |series, copies| Lines {
        history,
        series,
        copies,
    };
    ui.horizontal(|ui| {
        for (id, title, lines) in [
            (
                "plot-omega",
                tr!("plots-omega-title"),
                lines(&OMEGA[..], &copies[..]),
            ),
            ("plot-l", tr!("plots-l-title"), lines(&MOMENTUM[..], &[])),
            (
                "plot-energy",
                tr!("plots-energy-title"),
                lines(&ENERGY[..], &[]),
            ),
        ] {
            ui.vertical(|ui| {
                ui.small(title);
                draw(ui, id, &lines, since, bounds, [width, height]);
            });
        }
    });
}

/// One plot, decimated to one point per two horizontal pixels (min and max of each four-pixel
/// bucket) so its cost does not grow with the history length: on software GL every feathered line
/// segment costs rasterisation time, and denser lines looked no different.
/// What one plot draws: the series of the body's history, and the same of each copy's, dashed.
struct Lines<'a> {
    history: &'a History,
    series: &'a [Series],
    copies: &'a [&'a History],
}

fn draw(
    ui: &mut egui::Ui,
    id: &str,
    lines: &Lines<'_>,
    since: f64,
    bounds: Option<(f64, f64)>,
    [width, height]: [f32; 2],
) {
    let max_points = (width as usize / 2).max(64);
    Plot::new(id)
        .legend(Legend::default())
        .link_axis(egui::Id::unique("plots-time"), [true, false])
        .link_cursor(egui::Id::unique("plots-time"), [true, false])
        .allow_scroll(false)
        // Coarser grid than egui_plot's default (8 px): fewer faint lines to blend on software GL.
        .grid_spacing(24.0..=200.0)
        // Numbers in the language's way ("0,5"), as egui_plot would write them otherwise.
        .x_axis_formatter(tick)
        .y_axis_formatter(tick)
        .label_formatter(|hovered| {
            let (name, at) = match hovered {
                HoverPosition::NearDataPoint {
                    plot_name,
                    position,
                    ..
                } => (*plot_name, *position),
                HoverPosition::Elsewhere { position } => ("", *position),
            };
            Some(format!(
                "{name}\nt = {} s\n{}",
                fixed(at.x, 2),
                sci(at.y, 3)
            ))
        })
        .width(width)
        .height(height)
        .show(ui, |p| {
            if let Some((a, b)) = bounds {
                p.set_plot_bounds_x(a..=b.max(a + 1e-3));
                p.set_auto_bounds([false, true]);
            }
            for (name, color, f) in lines.series {
                let points = lines.history.series(since, max_points, f);
                p.line(
                    Line::new(*name, PlotPoints::new(points))
                        .color(*color)
                        .width(1.0),
                );
                // Same name: the legend entry shows and hides the copies' curves too.
                for copy in lines.copies {
                    let points = copy.series(since, max_points, f);
                    p.line(
                        Line::new(*name, PlotPoints::new(points))
                            .color(*color)
                            .width(1.0)
                            .style(LineStyle::dashed_dense()),
                    );
                }
            }
        });
}

/// A tick's number with as many decimals as its step needs (egui_plot's rule), in the
/// language's way.
fn tick(mark: GridMark, _range: &std::ops::RangeInclusive<f64>) -> String {
    let decimals = (-mark.step_size.log10().round()).max(0.0) as usize;
    fixed(mark.value, decimals)
}

/// The energy drift readout.
fn drift_text(lab: &Lab) -> String {
    let primary = lab.primary();
    if primary.string_view().is_some() {
        return tr!("plots-drift-string");
    }
    match primary.history().energy_drift() {
        Some((now, max)) => tr!(
            "plots-drift",
            now = localize(format!("{now:+.2e}")),
            max = sci(max, 2)
        ),
        None => tr!("plots-drift-none"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ticks take as many decimals as their step needs, with the language's separator.
    #[test]
    fn ticks_are_written_in_the_language_s_way() {
        let mark = |value, step_size| GridMark { value, step_size };
        crate::i18n::set_language(crate::i18n::Language::German);
        assert_eq!(tick(mark(0.5, 0.1), &(0.0..=1.0)), "0,5");
        assert_eq!(tick(mark(0.0002, 0.0001), &(0.0..=1.0)), "0,0002");
        assert_eq!(tick(mark(20.0, 10.0), &(0.0..=1.0)), "20");
        crate::i18n::set_language(crate::i18n::Language::English);
        assert_eq!(tick(mark(0.5, 0.1), &(0.0..=1.0)), "0.5");
    }
}
