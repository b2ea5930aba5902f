//! `usd`: a whole USD stage in text form (`.usda`): the body an `Xform` with UsdPhysics'
//! `PhysicsRigidBodyAPI` and `PhysicsMassAPI`, its surface a `Mesh` child with
//! `PhysicsCollisionAPI`, metres and kilograms stated in the stage's metadata.
//!
//! UsdPhysics (Pixar, `usdPhysics/schema.usda`, `MassAPI`): `physics:mass` (kg),
//! `physics:centerOfMass` ("center of mass in the prim's local space"), `physics:diagonalInertia`
//! ("diagonalized inertia tensor along the principal axes") and `physics:principalAxes`
//! ("orientation of the inertia tensor's principal axes in the prim's local space"), a `quatf`
//! written `(real, i, j, k)`. The schema types them single precision (`float`, `point3f`,
//! `float3`, `quatf`), so the full double-precision figures are written beside them as
//! `inertialab:` attributes, with the tensor itself (off-diagonals −∑m·x·y). Stage metadata:
//! `metersPerUnit` (UsdGeom), `kilogramsPerUnit` (UsdPhysics), `upAxis` "Z": Omniverse's and
//! Isaac Sim's axes, right-handed.
//!
//! With a baked [`Motion`], the `Xform` carries time-sampled `xformOp:translate` (`double3`) and
//! `xformOp:orient` (`quatd`), applied in that order (USD's `xformOpOrder`: the point is turned,
//! then moved), one sample a frame at time code k = frame k, with `timeCodesPerSecond` the frame
//! rate, and `physics:kinematicEnabled` so that a physics engine plays the baked motion rather
//! than simulating the body again (UsdPhysics: "a kinematic body is a body that is moved through
//! animated poses").

use std::fmt::Write as _;

use super::frames::{Converted, num};
use super::motion::Motion;
use super::surface::Surface;

/// The `.usda` text.
pub fn render(
    body: &Converted,
    surface: &Surface,
    name: &str,
    animation: Option<&Motion>,
) -> String {
    let s = body.conversion.source_unit.metres() / body.conversion.target_unit.metres();
    // USD prim names are identifiers.
    let prim = super::identifier(name);
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    let i = &body.inertia;
    let mut out = String::new();
    let _ = writeln!(out, "#usda 1.0");
    let _ = writeln!(out, "(");
    let _ = writeln!(out, "    defaultPrim = \"{prim}\"");
    let _ = writeln!(
        out,
        "    doc = \"{} UsdPhysics MassAPI: mass kg, centerOfMass m in the body's space, \
         diagonalInertia = principal moments kg*m^2 about the centre of mass, principalAxes = \
         (w, x, y, z) rotating the principal axes to the body's axes (tensor = R diag R^T); \
         inertialab: attributes repeat them in double precision.\"",
        escape(&super::provenance(body))
    );
    let _ = writeln!(out, "    metersPerUnit = 1");
    let _ = writeln!(out, "    kilogramsPerUnit = 1");
    let _ = writeln!(out, "    upAxis = \"Z\"");
    let frames = animation.map(|a| (a.fps, a.in_target(body)));
    if let Some((fps, frames)) = &frames {
        let _ = writeln!(out, "    timeCodesPerSecond = {}", num(*fps));
        let _ = writeln!(out, "    framesPerSecond = {}", num(*fps));
        let _ = writeln!(out, "    startTimeCode = 0");
        let _ = writeln!(out, "    endTimeCode = {}", frames.len().saturating_sub(1));
    }
    let _ = writeln!(out, ")");
    let _ = writeln!(out);
    let _ = writeln!(out, "def Xform \"{prim}\" (");
    let _ = writeln!(
        out,
        "    prepend apiSchemas = [\"PhysicsRigidBodyAPI\", \"PhysicsMassAPI\"]"
    );
    let _ = writeln!(out, ")");
    let _ = writeln!(out, "{{");
    if let Some((_, frames)) = &frames {
        write_samples(&mut out, frames);
    }
    let _ = writeln!(out, "    float physics:mass = {}", num(body.mass));
    let _ = writeln!(
        out,
        "    point3f physics:centerOfMass = ({}, {}, {})",
        num(c.x),
        num(c.y),
        num(c.z)
    );
    let _ = writeln!(
        out,
        "    float3 physics:diagonalInertia = ({}, {}, {})",
        num(m.x),
        num(m.y),
        num(m.z)
    );
    let _ = writeln!(
        out,
        "    quatf physics:principalAxes = ({}, {}, {}, {})",
        num(w),
        num(x),
        num(y),
        num(z)
    );
    let _ = writeln!(out, "    double inertialab:mass = {}", num(body.mass));
    let _ = writeln!(
        out,
        "    double3 inertialab:centerOfMass = ({}, {}, {})",
        num(c.x),
        num(c.y),
        num(c.z)
    );
    let _ = writeln!(
        out,
        "    double3 inertialab:diagonalInertia = ({}, {}, {})",
        num(m.x),
        num(m.y),
        num(m.z)
    );
    let _ = writeln!(
        out,
        "    quatd inertialab:principalAxes = ({}, {}, {}, {})",
        num(w),
        num(x),
        num(y),
        num(z)
    );
    let _ = writeln!(
        out,
        "    matrix3d inertialab:inertia = ( ({}, {}, {}), ({}, {}, {}), ({}, {}, {}) )",
        num(i[(0, 0)]),
        num(i[(0, 1)]),
        num(i[(0, 2)]),
        num(i[(1, 0)]),
        num(i[(1, 1)]),
        num(i[(1, 2)]),
        num(i[(2, 0)]),
        num(i[(2, 1)]),
        num(i[(2, 2)])
    );
    let _ = writeln!(out);
    let _ = writeln!(out, "    def Mesh \"Surface\" (");
    let _ = writeln!(
        out,
        "        prepend apiSchemas = [\"PhysicsCollisionAPI\", \"PhysicsMeshCollisionAPI\"]"
    );
    let _ = writeln!(out, "    )");
    let _ = writeln!(out, "    {{");
    let _ = writeln!(
        out,
        "        uniform token physics:approximation = \"convexDecomposition\""
    );
    let _ = writeln!(out, "        uniform token subdivisionScheme = \"none\"");
    let _ = writeln!(out, "        uniform token orientation = \"rightHanded\"");
    let _ = write!(out, "        int[] faceVertexCounts = [");
    join(&mut out, surface.triangles.iter().map(|_| "3".to_owned()));
    let _ = writeln!(out, "]");
    let _ = write!(out, "        int[] faceVertexIndices = [");
    join(
        &mut out,
        surface.triangles.iter().flatten().map(|i| i.to_string()),
    );
    let _ = writeln!(out, "]");
    let _ = write!(out, "        point3f[] points = [");
    join(
        &mut out,
        surface.points.iter().map(|p| {
            let q = body.map * p.coords * s;
            format!("({}, {}, {})", num(q.x), num(q.y), num(q.z))
        }),
    );
    let _ = writeln!(out, "]");
    let _ = writeln!(out, "    }}");
    let _ = writeln!(out, "}}");
    out
}

/// The time-sampled transform ops of the keyframes and their order.
fn write_samples(
    out: &mut String,
    frames: &[(nalgebra::UnitQuaternion<f64>, nalgebra::Vector3<f64>)],
) {
    let _ = writeln!(out, "    bool physics:kinematicEnabled = 1");
    let _ = writeln!(out, "    double3 xformOp:translate.timeSamples = {{");
    for (k, (_, t)) in frames.iter().enumerate() {
        let _ = writeln!(
            out,
            "        {k}: ({}, {}, {}),",
            num(t.x),
            num(t.y),
            num(t.z)
        );
    }
    let _ = writeln!(out, "    }}");
    let _ = writeln!(out, "    quatd xformOp:orient.timeSamples = {{");
    for (k, (q, _)) in frames.iter().enumerate() {
        let _ = writeln!(
            out,
            "        {k}: ({}, {}, {}, {}),",
            num(q.w),
            num(q.i),
            num(q.j),
            num(q.k)
        );
    }
    let _ = writeln!(out, "    }}");
    let _ = writeln!(
        out,
        "    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:orient\"]"
    );
}

/// Items separated by ", ".
fn join(out: &mut String, items: impl Iterator<Item = String>) {
    for (k, item) in items.enumerate() {
        if k > 0 {
            out.push_str(", ");
        }
        out.push_str(&item);
    }
}

/// A string for a double-quoted USD string.
fn escape(text: &str) -> String {
    text.replace('\\', "\\\\").replace('"', "\\\"")
}
