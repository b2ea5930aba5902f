//! Each built-in lesson completed by driving the lab as a student would (the commands the panels
//! send), with the checks' own measurements asserted; and the lesson format's errors.

use nalgebra::Vector3;

use super::*;
use crate::lab::settings::{AppSettings, InertiaSource};
use crate::lab::{Command, Lab, PRIMARY};

fn lab() -> Lab {
    Lab::new(AppSettings::default()).expect("the lab")
}

fn open(lab: &mut Lab, key: &str) {
    lab.apply(Command::OpenLesson(LessonSource::BuiltIn(key.to_owned())));
    assert!(
        lab.message().is_none_or(|m| !m.error),
        "{:?}",
        lab.message()
    );
    assert_eq!(lab.lesson().expect("open").step, 0);
}

fn run(lab: &Lab) -> &LessonRun {
    lab.lesson().expect("a lesson is open")
}

/// Runs simulated time until the step is done, at most `seconds` of it; fails with the checks'
/// state.
fn until_done(lab: &mut Lab, seconds: f64) {
    let mut t = 0.0;
    while !run(lab).step_done() && t < seconds {
        let before = lab.primary().sim().time();
        lab.advance_for(0.5);
        t += (lab.primary().sim().time() - before).max(1e-3);
    }
    assert!(
        run(lab).step_done(),
        "step {} not done after {seconds} s: {:?}",
        run(lab).step + 1,
        run(lab).checks
    );
}

/// Runs `seconds` of simulated time (a frame's catch-up cap limits each advance).
fn run_for(lab: &mut Lab, seconds: f64) {
    let end = lab.primary().sim().time() + seconds;
    while lab.primary().sim().time() < end {
        lab.advance_for(0.5);
    }
}

/// Commits to the right answer of the step's prediction (a wrong one works as well).
fn predict_right(lab: &mut Lab) {
    let answer = run(lab)
        .current()
        .predict
        .as_ref()
        .expect("a prediction")
        .answer;
    assert!(lab.is_paused(), "the lab waits for the prediction");
    lab.apply(Command::Predict(answer));
    assert!(!lab.is_paused());
    assert_eq!(run(lab).prediction, Some(answer));
}

fn next(lab: &mut Lab) {
    let step = run(lab).step;
    lab.apply(Command::NextStep);
    assert_eq!(run(lab).step, step + 1, "{:?}", lab.message());
}

fn set(lab: &mut Lab, change: impl FnOnce(&mut AppSettings)) {
    let mut s = lab.settings().clone();
    change(&mut s);
    lab.apply(Command::Settings(Box::new(s)));
    assert!(
        lab.message().is_none_or(|m| !m.error),
        "{:?}",
        lab.message()
    );
}

fn finished(lab: &Lab, id: &str, steps: usize) {
    let r = run(lab);
    assert!(r.finished(), "{:?}", r.checks);
    assert_eq!(r.progress(), "done");
    assert_eq!(lab.lesson_progress().get(id), Some(&steps));
}

#[test]
fn eight_lessons_are_built_in_and_found_by_number_and_id() {
    let all = built_in();
    assert_eq!(all.len(), 8);
    assert_eq!(find("1").expect("first").id, "tensor");
    assert_eq!(
        find("racket-flip").expect("by id").title,
        "The tennis-racket flip"
    );
    let e = find("9").expect_err("none").to_string();
    assert!(e.contains("1 to 8") && e.contains("your-object"), "{e}");
}

#[test]
fn lesson_1_the_tensor_against_the_bounding_box() {
    let mut lab = lab();
    open(&mut lab, "1");
    assert_eq!(lab.primary().body().name, "L-bracket");
    assert_eq!(run(&lab).progress(), "1/2");
    // The checks wait for the prediction: switching first does not count.
    predict_right(&mut lab);
    assert!(!run(&lab).step_done());
    set(&mut lab, |s| s.body.source = InertiaSource::BoundingBox);
    assert!(run(&lab).step_done());
    next(&mut lab);
    set(&mut lab, |s| s.body.source = InertiaSource::Exact);
    finished(&lab, "tensor", 2);
}

#[test]
fn lesson_2_stable_and_unstable_axes() {
    let mut lab = lab();
    open(&mut lab, "stable-axes");
    until_done(&mut lab, 12.0);
    next(&mut lab);
    // The second step's checks wait for the spin about axis 3.
    run_for(&mut lab, 12.0);
    assert!(!run(&lab).step_done());
    lab.apply(Command::Preset(2));
    until_done(&mut lab, 12.0);
    next(&mut lab);
    predict_right(&mut lab);
    until_done(&mut lab, 30.0);
    finished(&lab, "stable-axes", 3);
}

#[test]
fn lesson_3_the_racket_flip_is_measured_as_predicted() {
    let mut lab = lab();
    open(&mut lab, "racket-flip");
    predict_right(&mut lab);
    until_done(&mut lab, 120.0);
    let found = run(&lab).checks[1].finding.clone().expect("measured");
    assert!(found.contains("predicted"), "{found}");
    next(&mut lab);
    assert!(lab.settings().view.poinsot && lab.settings().view.momentum_sphere);
    until_done(&mut lab, 120.0);
    finished(&lab, "racket-flip", 2);
}

#[test]
fn lesson_4_the_textbook_model_never_flips() {
    let mut lab = lab();
    open(&mut lab, "textbook-model");
    predict_right(&mut lab);
    // Under the full model the T-handle reverses within 20 s: the check does not hold.
    run_for(&mut lab, 21.0);
    assert!(!run(&lab).step_done(), "{:?}", run(&lab).checks);
    set(&mut lab, |s| {
        s.physics.model = rbcore::RotationModel::Textbook
    });
    until_done(&mut lab, 25.0);
    next(&mut lab);
    set(&mut lab, |s| s.physics.model = rbcore::RotationModel::Full);
    until_done(&mut lab, 30.0);
    finished(&lab, "textbook-model", 2);
}

#[test]
fn lesson_5_moving_the_head_changes_i_by_the_parallel_axis_theorem() {
    let mut lab = lab();
    open(&mut lab, "parallel-axis");
    predict_right(&mut lab);
    let mut head = lab
        .primary()
        .body()
        .composition
        .as_ref()
        .expect("parts")
        .parts[0]
        .entry
        .clone();
    // 5 cm is too little.
    head.translation[1] += 0.05;
    lab.apply(Command::EditPart {
        index: 0,
        entry: Box::new(head.clone()),
        visible: true,
    });
    assert!(!run(&lab).step_done());
    head.translation[1] += 0.07;
    lab.apply(Command::EditPart {
        index: 0,
        entry: Box::new(head),
        visible: true,
    });
    assert!(run(&lab).step_done(), "{:?}", run(&lab).checks);
    let found = run(&lab).checks[1].finding.clone().expect("measured");
    assert!(found.contains("moved 0.120 m"), "{found}");
    next(&mut lab);
    until_done(&mut lab, 6.0);
    finished(&lab, "parallel-axis", 2);
}

/// The check itself: a part moved with its tensor changed otherwise than m(|p|²E − ppᵀ) fails.
#[test]
fn the_parallel_axis_check_fails_when_the_tensor_does_not_follow() {
    let mut lab = lab();
    open(&mut lab, "parallel-axis");
    predict_right(&mut lab);
    let mut head = lab
        .primary()
        .body()
        .composition
        .as_ref()
        .expect("parts")
        .parts[0]
        .entry
        .clone();
    // Moved and made of another material: the mass changed, so the theorem's m is not the
    // part's any more and the check must not pass.
    head.translation[1] += 0.2;
    head.material = massprops::MaterialEntry::Preset("aluminium".to_owned());
    lab.apply(Command::EditPart {
        index: 0,
        entry: Box::new(head),
        visible: true,
    });
    assert!(!run(&lab).checks[1].met);
}

#[test]
fn lesson_6_a_poke_changes_l_by_r_cross_j() {
    let mut lab = lab();
    open(&mut lab, "conservation");
    until_done(&mut lab, 12.0);
    next(&mut lab);
    predict_right(&mut lab);
    let centre = lab.primary().sim().body().position();
    lab.apply(Command::Poke {
        specimen: PRIMARY,
        point: centre + Vector3::new(0.03, 0.01, 0.0),
        direction: Vector3::new(0.0, 0.0, -1.0),
    });
    assert!(run(&lab).step_done(), "{:?}", run(&lab).checks);
    next(&mut lab);
    until_done(&mut lab, 12.0);
    finished(&lab, "conservation", 3);
}

#[test]
fn lesson_7_a_racket_that_flips_every_4_s_then_one_that_cannot() {
    let mut lab = lab();
    open(&mut lab, "design-a-body");
    let period = 2.0 * lab.primary().turn_over_interval().expect("a flip");
    assert!(
        (period - 4.0).abs() > 0.2,
        "the start is not the answer: {period}"
    );
    // The period scales as 1/ω: spin faster by period / 4.
    let rate = lab.settings().body.spin_rate * period / 4.0;
    set(&mut lab, |s| s.body.spin_rate = rate);
    lab.apply(Command::Preset(1));
    assert!(run(&lab).step_done(), "{:?}", run(&lab).checks);
    next(&mut lab);
    assert!(!run(&lab).step_done());
    lab.apply(Command::LoadSample("Cube".to_owned()));
    finished(&lab, "design-a-body", 2);
}

#[test]
fn lesson_8_your_own_object() {
    let mut lab = lab();
    open(&mut lab, "your-object");
    lab.apply(Command::LoadSample("Book".to_owned()));
    assert!(!run(&lab).step_done(), "a sample is not the student's own");
    let dir = std::env::temp_dir().join(format!("lesson-8-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a folder");
    let file = dir.join("phone.obj");
    let phone =
        massprops::shapes::cuboid(Vector3::new(0.07, 0.15, 0.008), nalgebra::Point3::origin());
    std::fs::write(&file, massprops::shapes::to_obj("phone", "phone", &phone)).expect("written");
    lab.apply(Command::LoadFile(file));
    lab.wait_for_load();
    lab.apply(Command::DismissMessage);
    assert!(run(&lab).step_done(), "{:?}", run(&lab).checks);
    next(&mut lab);
    predict_right(&mut lab);
    until_done(&mut lab, 11.0);
    finished(&lab, "your-object", 2);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn next_waits_for_the_checks_and_back_sets_the_step_up_again() {
    let mut lab = lab();
    open(&mut lab, "stable-axes");
    lab.apply(Command::NextStep);
    assert_eq!(run(&lab).step, 0);
    assert!(lab.message().is_some_and(|m| m.error));
    until_done(&mut lab, 12.0);
    next(&mut lab);
    lab.apply(Command::Preset(2));
    lab.apply(Command::PreviousStep);
    assert_eq!(run(&lab).step, 0);
    assert_eq!(lab.preset_axis(), 0, "step 1's spin set up again");
    lab.apply(Command::CloseLesson);
    assert!(lab.lesson().is_none());
    assert_eq!(lab.lesson_progress().get("stable-axes"), Some(&1));
}

#[test]
fn a_teachers_lesson_file_opens_and_its_mistakes_are_named() {
    let text = "id = \"mine\"\ntitle = \"Mine\"\ngoal = \"g\"\n[[step]]\ntext = \"t\"\n\
                explain = \"e\"\ncheck = [{ kind = \"spin_axis\", axis = 3 }]\n";
    let mut lab = lab();
    lab.apply(Command::OpenLesson(LessonSource::Text {
        file: "mine.toml".to_owned(),
        text: text.to_owned(),
    }));
    assert!(!run(&lab).step_done());
    lab.apply(Command::Preset(2));
    assert!(run(&lab).finished());

    let bad = |text: &str| {
        Lesson::parse("bad.toml", text)
            .expect_err("refused")
            .to_string()
    };
    let e = bad(&text.replace("axis = 3", "axis = 4"));
    assert!(
        e.contains("bad.toml") && e.contains("step 1") && e.contains("1, 2 or 3"),
        "{e}"
    );
    let e = bad(&text.replace("spin_axis", "spin_axle"));
    assert!(e.contains("bad.toml") && e.contains("spin_axle"), "{e}");
    let e = bad(&text.replace("[[step]]", "[[step]]\nsetup = { sample = \"Bike\" }"));
    assert!(e.contains("no sample \"Bike\""), "{e}");
    let e = bad("id = \"x\"\ntitle = \"t\"\ngoal = \"g\"\nstep = []\n");
    assert!(e.contains("at least one"), "{e}");
}

/// Each built-in lesson speaks German and Spanish: every title, goal, step, question, choice and
/// explanation has its own words there (an untranslated copy of the English fails), and what a
/// step sets up and checks stays the lesson's.
#[test]
fn every_built_in_lesson_has_its_words_in_every_language() {
    for lesson in built_in() {
        for language in TRANSLATED {
            let said = lesson.in_language(language);
            let code = language.code();
            assert_ne!(said.title, lesson.title, "{code}: {}", lesson.id);
            assert_ne!(said.goal, lesson.goal, "{code}: {}", lesson.id);
            for (k, (theirs, ours)) in said.steps.iter().zip(&lesson.steps).enumerate() {
                let at = format!("{code}: {} step {}", lesson.id, k + 1);
                assert_ne!(theirs.text, ours.text, "{at}");
                assert_ne!(theirs.explain, ours.explain, "{at}");
                assert_eq!(theirs.checks, ours.checks, "{at}");
                assert_eq!(theirs.setup, ours.setup, "{at}");
                if let (Some(p), Some(q)) = (&theirs.predict, &ours.predict) {
                    assert_ne!(p.question, q.question, "{at}");
                    assert_eq!(p.answer, q.answer, "{at}");
                    // A choice that is a formula alone ("r × J") reads the same everywhere.
                    let words =
                        |c: &str| c.split(|c: char| !c.is_alphabetic()).any(|w| w.len() >= 3);
                    for (a, b) in p.choices.iter().zip(&q.choices).filter(|(_, b)| words(b)) {
                        assert_ne!(a, b, "{at}");
                    }
                }
            }
        }
        assert_eq!(lesson.in_language(Language::English), *lesson);
    }
}

/// Words that do not fit the lesson's steps, questions or choices are refused, naming the file.
#[test]
fn a_translation_that_does_not_fit_the_lesson_is_refused() {
    let lesson = find("1").expect("lesson 1");
    let steps = |n: usize, choices: &str| {
        let mut text = "title = \"T\"\ngoal = \"G\"\n".to_owned();
        for k in 0..n {
            text.push_str("[[step]]\ntext = \"x\"\nexplain = \"y\"\n");
            if k == 0 {
                text.push_str(&format!("question = \"q\"\nchoices = [{choices}]\n"));
            }
        }
        text
    };
    let mut fresh = (*lesson).clone();
    fresh.translations.clear();
    let e = fresh
        .clone()
        .translate(
            Language::German,
            "de/x.toml",
            &steps(1, "\"a\", \"b\", \"c\""),
        )
        .expect_err("one step of two");
    assert!(
        e.to_string().contains("de/x.toml") && e.to_string().contains("1 steps"),
        "{e}"
    );
    let e = fresh
        .clone()
        .translate(Language::German, "de/x.toml", &steps(2, "\"a\", \"b\""))
        .expect_err("two choices of three");
    assert!(e.to_string().contains("step 1"), "{e}");
    let mut fits = fresh.clone();
    fits.translate(
        Language::German,
        "de/x.toml",
        &steps(2, "\"a\", \"b\", \"c\""),
    )
    .expect("fits");
    let said = fits.in_language(Language::German);
    assert_eq!(said.title, "T");
    assert_eq!(
        said.steps[0].predict.as_ref().map(|p| p.choices.len()),
        Some(3)
    );
    assert_eq!(said.steps[1].text, "x");
    let own = fits.in_language(Language::Spanish);
    assert_eq!(
        (own.title, own.steps),
        (fresh.title, fresh.steps),
        "no Spanish: its own words"
    );
}
