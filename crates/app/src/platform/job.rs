//! Work given away from the UI thread as a [`Job`]: its input, its progress reports and its
//! output are plain data, so the same job runs on a thread of its own on the desktop and in the
//! page's worker in a browser (another instance of the same wasm module, on another thread of
//! the browser's), where they cross as bytes ([`encode`], postcard's compact format).

use serde::Serialize;
use serde::de::DeserializeOwned;

/// Work that takes its input, reports progress, and ends with its output.
pub trait Job: 'static {
    /// The name the page's worker knows the job by (the web crate lists the jobs it runs).
    const NAME: &'static str;
    /// What it is given.
    type Input: Serialize + DeserializeOwned + Send + 'static;
    /// What it reports on its way.
    type Progress: Serialize + DeserializeOwned + Send + 'static;
    /// What it gives back (errors included: a job always ends with an output).
    type Output: Serialize + DeserializeOwned + Send + 'static;

    /// Does the work, calling `progress` as it goes.
    fn run(input: Self::Input, progress: &dyn Fn(Self::Progress)) -> Self::Output;
}

/// What a started job tells whoever started it.
#[derive(Debug)]
pub enum JobEvent<J: Job> {
    /// A report on its way.
    Progress(J::Progress),
    /// Its output; nothing follows.
    Done(J::Output),
    /// It will never end: where it ran failed (the worker could not start, or stopped), in
    /// that place's words; nothing follows.
    Lost(String),
}

/// The bytes that carry `value` to the worker or back.
///
/// # Errors
/// The value cannot be written as data (postcard's words).
pub fn encode<T: Serialize>(value: &T) -> Result<Vec<u8>, String> {
    postcard::to_stdvec(value).map_err(|e| e.to_string())
}

/// The value that `bytes` carry.
///
/// # Errors
/// The bytes are not such a value (postcard's words).
pub fn decode<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, String> {
    postcard::from_bytes(bytes).map_err(|e| e.to_string())
}

/// Runs job `J` on its encoded `input` where it was sent (the page's worker): each report and
/// then the output go back encoded through `post(done, bytes)`, `done` true for the output.
///
/// # Errors
/// The input or a report could not be read or written (the job does not run, or its output is
/// not sent).
pub fn serve<J: Job>(input: &[u8], post: &dyn Fn(bool, Vec<u8>)) -> Result<(), String> {
    let input: J::Input = decode(input)?;
    let failed = std::cell::RefCell::new(None);
    let output = J::run(input, &|p| match encode(&p) {
        Ok(bytes) => post(false, bytes),
        Err(e) => {
            failed.replace(Some(e));
        }
    });
    if let Some(e) = failed.into_inner() {
        return Err(e);
    }
    post(true, encode(&output)?);
    Ok(())
}

/// Reads what [`serve`] posted, as the starter of job `J` hears it.
pub fn event_of<J: Job>(done: bool, bytes: &[u8]) -> JobEvent<J> {
    let event = if done {
        decode(bytes).map(JobEvent::Done)
    } else {
        decode(bytes).map(JobEvent::Progress)
    };
    event.unwrap_or_else(|e| JobEvent::Lost(format!("{}: unreadable reply: {e}", J::NAME)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sums its numbers, reporting each partial sum.
    #[derive(Debug)]
    struct Sum;

    impl Job for Sum {
        const NAME: &'static str = "sum";
        type Input = Vec<f64>;
        type Progress = f64;
        type Output = Result<f64, String>;

        fn run(input: Vec<f64>, progress: &dyn Fn(f64)) -> Result<f64, String> {
            let mut total = 0.0;
            for x in input {
                total += x;
                progress(total);
            }
            if total.is_finite() {
                Ok(total)
            } else {
                Err("not finite".into())
            }
        }
    }

    /// What a job sends through the wire is what it reports and returns, in order.
    #[test]
    fn a_served_job_reaches_its_starter_as_it_ran() {
        let posted = std::cell::RefCell::new(Vec::new());
        let input = encode(&vec![0.5, 0.25, 2.0]).expect("encodes");
        serve::<Sum>(&input, &|done, bytes| {
            posted.borrow_mut().push((done, bytes))
        })
        .expect("runs");
        let heard: Vec<String> = posted
            .into_inner()
            .iter()
            .map(|(done, bytes)| match event_of::<Sum>(*done, bytes) {
                JobEvent::Progress(p) => format!("progress {p}"),
                JobEvent::Done(out) => format!("done {out:?}"),
                JobEvent::Lost(e) => format!("lost {e}"),
            })
            .collect();
        assert_eq!(
            heard,
            [
                "progress 0.5",
                "progress 0.75",
                "progress 2.75",
                "done Ok(2.75)"
            ]
        );
    }

    /// Bytes that are not the job's say so, with the job's name, instead of panicking.
    #[test]
    fn unreadable_bytes_are_a_lost_job_and_a_refused_input() {
        match event_of::<Sum>(true, &[0xff]) {
            JobEvent::Lost(e) => assert!(e.starts_with("sum: unreadable reply"), "{e}"),
            other => panic!("{other:?}"),
        }
        assert!(serve::<Sum>(&[0xff, 0xff, 0xff], &|_, _| panic!("posted")).is_err());
    }
}
