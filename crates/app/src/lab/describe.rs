//! What is happening, in words, for a student who cannot see the 3D view, the plots or the
//! momentum sphere: written from the lab's state, for the desktop's accessibility tree and the
//! page's live region (`aria-live`).
//!
//! The text changes when something happens (a reversal of ω₂, a new spin, a pause, a poke),
//! not every frame: it states times as simulated times of events ("reversed at t = 12.4 s"),
//! never as a running "ago", and rates to two significant digits, so that a screen reader is
//! not made to read it again sixty times a second.

use rbcore::{Polhode, RotationModel};

use super::Lab;
use crate::i18n::{fixed, localize, tr};
use crate::lab::specimen::TURNING_OVER;

/// The description of the primary specimen's motion.
pub fn description(lab: &Lab) -> String {
    let s = lab.primary();
    let b = s.sim().body();
    let name = &s.body().name;
    // The spin about L, ω·L/|L| = 2T/|L|: held through a torque-free tumble, where |ω| is not.
    let l = b.angular_momentum();
    let omega = if l.norm() > 0.0 {
        b.omega_world().dot(&l) / l.norm()
    } else {
        0.0
    };
    let mut text = if omega.abs() < 1e-9 {
        tr!("describe-at-rest", name = name)
    } else {
        let w = s.sim().diagnostics().omega_principal;
        let main = (0..3)
            .max_by(|&i, &j| w[i].abs().total_cmp(&w[j].abs()))
            .unwrap_or(0);
        tr!(
            "describe-spins",
            name = name,
            rate = two_digits(omega),
            axis = main + 1
        )
    };
    // Each further sentence follows a space (a message's text cannot begin with one).
    let mut add = |sentence: String| {
        text.push(' ');
        text.push_str(&sentence);
    };
    let history = s.history();
    match s.polhode() {
        Polhode::Circles { axis, .. } if s.cone_angle() >= TURNING_OVER => {
            match (history.last_reversal(), s.turn_over_interval()) {
                (Some(last), Some(half)) => add(tr!(
                    "describe-reversed",
                    last = fixed(last, 1),
                    next = fixed(last + half, 1)
                )),
                (None, Some(half)) => add(tr!(
                    "describe-will-turn-over",
                    half = fixed(half, 1),
                    axis = axis + 1
                )),
                (_, None) => {}
            }
        }
        Polhode::Circles { axis, .. } => add(tr!(
            "describe-wobbles",
            axis = axis + 1,
            angle = fixed(s.cone_angle().to_degrees(), 0)
        )),
        Polhode::Steady { axis } => add(tr!("describe-steady", axis = axis + 1)),
        Polhode::Separatrix => add(tr!("describe-separatrix")),
        Polhode::AtRest | Polhode::Spherical => {}
    }
    if s.sim().settings().model == RotationModel::Textbook {
        add(tr!("describe-textbook"));
    }
    if lab.is_paused() {
        add(tr!("describe-paused", time = fixed(s.sim().time(), 1)));
    }
    let copies = lab.specimens().len() - 1;
    if copies > 0 {
        add(tr!("describe-copies", copies = copies));
    }
    text
}

/// The open lesson in words: its title, the step and its text, the prediction asked or made, and
/// which checks have held (not what they measure, which changes every frame); `None` without a
/// lesson.
pub fn lesson(lab: &Lab) -> Option<String> {
    let run = lab.lesson()?;
    let lesson = run.lesson.in_language(crate::i18n::language());
    let step = &lesson.steps[run.step];
    let paragraph = |text: &str| text.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut text = tr!(
        "describe-lesson",
        title = &lesson.title,
        step = run.step + 1,
        steps = lesson.steps.len(),
        text = paragraph(&step.text)
    );
    let mut add = |sentence: String| {
        text.push(' ');
        text.push_str(&sentence);
    };
    if let Some(p) = &step.predict {
        match run.prediction {
            None => add(tr!(
                "describe-predict",
                question = &p.question,
                choices = p.choices.join("; ")
            )),
            Some(k) => add(tr!("describe-predicted", choice = &p.choices[k])),
        }
    }
    if !run.awaits_prediction() && !step.checks.is_empty() {
        let held = run.checks.iter().filter(|c| c.met).count();
        add(tr!(
            "describe-checks-held",
            held = held,
            checks = step.checks.len()
        ));
    }
    if run.step_done() {
        add(tr!("describe-done", explain = paragraph(&step.explain)));
    }
    Some(text)
}

/// `v` to two significant digits, as text in the language's decimal separator.
fn two_digits(v: f64) -> String {
    localize(significant(v, 2))
}

/// `v` to `digits` significant digits, without an exponent for the sizes a spin has, in the C
/// locale.
fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    let decimals = (digits - 1 - magnitude).max(0) as usize;
    let step = 10f64.powi(magnitude - digits + 1);
    format!("{:.decimals$}", (v / step).round() * step)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lab::{Command, Lab};

    #[test]
    fn significant_digits() {
        assert_eq!(significant(8.04, 2), "8.0");
        assert_eq!(significant(12.6, 2), "13");
        assert_eq!(significant(0.0314, 2), "0.031");
    }

    /// The T-handle spun about axis 2: the words say so, name the reversal once it happened
    /// and the next one predicted half a period on, and stay the same between events.
    #[test]
    fn the_flip_is_told_with_its_reversals() {
        let mut lab = Lab::new(crate::lab::settings::AppSettings::default()).expect("the lab");
        lab.apply(Command::Preset(1));
        let first = description(&lab);
        assert!(
            first.contains("mostly about axis 2") && first.contains("will turn over"),
            "{first}"
        );
        let half = lab.primary().turn_over_interval().expect("a flip");
        lab.advance_for(half * 0.4);
        assert_eq!(description(&lab), first, "nothing happened yet");
        lab.advance_for(half);
        let after = description(&lab);
        let last = lab.primary().history().last_reversal().expect("a reversal");
        assert!(
            after.contains(&format!("reversed at t = {last:.1} s"))
                && after.contains(&format!("predicted at t = {:.1} s", last + half)),
            "{after}"
        );
        lab.apply(Command::Preset(2));
        let steady = description(&lab);
        assert!(steady.contains("wobbles about axis 3"), "{steady}");
    }

    /// In German the description takes the decimal comma, and the compared copies their plural
    /// in each language.
    #[test]
    fn the_description_speaks_the_thread_s_language() {
        use crate::i18n::{Arg, Language, set_language, text_in};
        let mut lab = Lab::new(crate::lab::settings::AppSettings::default()).expect("the lab");
        lab.apply(Command::Preset(1));
        let half = lab.primary().turn_over_interval().expect("a flip");
        set_language(Language::German);
        let german = description(&lab);
        set_language(Language::English);
        let every = format!("alle {half:.1} s").replace('.', ",");
        assert!(
            german.contains("überwiegend um Achse 2") && german.contains(&every),
            "{german}"
        );
        let copies =
            |language, n: usize| text_in(language, "describe-copies", &[("copies", Arg::from(n))]);
        assert_eq!(
            copies(Language::English, 1),
            "1 compared copy runs beside it."
        );
        assert_eq!(
            copies(Language::English, 2),
            "2 compared copies run beside it."
        );
        assert_eq!(
            copies(Language::German, 1),
            "Eine verglichene Kopie läuft daneben."
        );
        assert_eq!(
            copies(Language::Spanish, 3),
            "3 copias comparadas se ejecutan a su lado."
        );
    }
}
