//! What every output says of its numbers, written once: the inertia tensor's sign convention
//! (every output states it), the principal axes' layout, and the `conventions` object of each
//! JSON output (props', audit's and the json export's), which is these and what that output
//! adds (its frame, units and the like).

use serde_json::{Map, Value};

/// The tensor sign convention, stated in every output (`props`, `audit` and every export format).
pub const TENSOR: &str =
    "inertia tensor I = sum m(|r|^2 E - r r^T): diagonal = moments, off-diagonals = -sum(m*x*y)";

/// How a JSON output lays out the principal axes.
pub const PRINCIPAL_AXES: &str =
    "row i is the unit axis of principal_moments[i]; rows form a right-handed orthonormal set";

/// A JSON output's `conventions` object: the tensor convention and `entries` (name, words).
pub fn block(entries: &[(&str, &str)]) -> Value {
    let mut map = Map::new();
    map.insert("tensor".to_owned(), Value::from(TENSOR));
    for (name, words) in entries {
        map.insert((*name).to_owned(), Value::from(*words));
    }
    Value::Object(map)
}
