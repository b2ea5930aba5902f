//! The language and display choices in the top bar: the language (or the system's), larger
//! text, reduced motion and, in a page, reading aloud.

use crate::gui::platform;
use crate::i18n::{Language, tr};
use crate::lab::settings::DisplaySettings;

/// Shows the language menu and the Display menu, editing the frame's settings draft; `system`
/// is the language "the system's" stands for.
pub(crate) fn show(ui: &mut egui::Ui, s: &mut DisplaySettings, system: Language) {
    let follows_system = tr!("display-language-system", language = system.endonym());
    let label = ui.label(tr!("display-language"));
    egui::ComboBox::from_id_salt("language")
        .selected_text(
            s.language
                .map_or(follows_system.clone(), |l| l.endonym().to_owned()),
        )
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut s.language, None, follows_system);
            for language in Language::ALL {
                ui.selectable_value(&mut s.language, Some(language), language.endonym());
            }
        })
        .response
        .labelled_by(label.id);
    ui.menu_button(tr!("display-menu"), |ui| {
        ui.checkbox(&mut s.larger_text, tr!("display-larger-text"))
            .on_hover_text(tr!("display-larger-text-hover"));
        ui.checkbox(&mut s.reduced_motion, tr!("display-reduced-motion"))
            .on_hover_text(tr!("display-reduced-motion-hover"));
        if platform::SELF_VOICING {
            ui.checkbox(&mut s.read_aloud, tr!("display-read-aloud"))
                .on_hover_text(tr!("display-read-aloud-hover"));
        }
    });
}

/// How much larger everything is drawn with "Larger text".
pub(crate) const LARGER_TEXT_ZOOM: f32 = 1.25;

/// Makes the context draw as `s` asks: its zoom, its animations and its own voice. Called when
/// the settings change (a zoom the user set with Ctrl and + stays until then).
pub(crate) fn apply(ctx: &egui::Context, s: &DisplaySettings) {
    ctx.set_zoom_factor(if s.larger_text { LARGER_TEXT_ZOOM } else { 1.0 });
    let animation_time = if s.reduced_motion {
        0.0
    } else {
        egui::Style::default().animation_time
    };
    ctx.all_styles_mut(|style| style.animation_time = animation_time);
    ctx.options_mut(|o| o.screen_reader = s.read_aloud && platform::SELF_VOICING);
}
