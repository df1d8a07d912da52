//! The declarations [`super::keys`] returns: one `Table` per table of the file form, its keys in the file form's
//! order. Wording follows the scene format's validation (`scene/validate/`); units are SI.

use super::{Key, Table};

/// A key: name, kind, unit, default, origin (positions only), meaning.
const fn key(
    name: &'static str,
    kind: &'static str,
    unit: &'static str,
    default: &'static str,
    origin: &'static str,
    doc: &'static str,
) -> Key {
    Key {
        name,
        kind,
        unit,
        default,
        origin,
        doc,
    }
}

/// Where a position in body axes is measured from.
const FROM_REFERENCE: &str = "the reference origin (the shape's center, or the point `inertia` is about), body axes";

/// The tables, in the file form's order.
pub(super) const TABLES: [Table; 13] = [
    Table {
        header: "",
        about: "the top level of the file",
        keys: &[
            key("name", "string", "–", "\"\"", "", "shown by `check` and in plot titles"),
            key("description", "string", "–", "\"\"", "", "one line, shown by `check`"),
            key("body", "table", "–", "required", "", "the body: `[body]`"),
            key("motion", "table", "–", "free rotation", "", "the motion: `[motion]`"),
            key("initial", "table", "–", "at rest, identity attitude", "", "the state at t = 0: `[initial]`"),
            key("effect", "array of tables", "–", "none: torque-free", "", "the moments applied: `[[effect]]`"),
            key("event", "array of tables", "–", "none", "", "moments to locate between rows: `[[event]]`"),
            key("solver", "table", "–", "required", "", "the integration: `[solver]`"),
            key("output", "table", "–", "required", "", "the rows written: `[output]`"),
            key("compare", "table", "–", "tolerance 1e-8", "", "what `eulerdyn compare` accepts: `[compare]`"),
        ],
    },
    Table {
        header: "[body]",
        about: "the rigid body: its mass and either a shape or an inertia tensor",
        keys: &[
            key("mass", "number", "kg", "required", "", "> 0; with point masses, the body without them"),
            key("shape", "inline table", "–", "one of `shape` / `inertia`", "", "a homogeneous shape: `[body.shape]`"),
            key("inertia", "[I1, I2, I3] or 3×3 array", "kg·m²", "one of `shape` / `inertia`", "", "about C in body axes: principal moments, or the symmetric tensor with I_xy = −∫xy dm; positive semi-definite, triangle inequality"),
            key("point_mass", "array of tables", "–", "none", "", "point masses rigidly attached: `[[body.point_mass]]`"),
            key("rotor", "array of tables", "–", "none", "", "wheels spinning inside the body (at most 4): `[[body.rotor]]`"),
        ],
    },
    Table {
        header: "[body.shape]",
        about: "a shape of uniform density (disks and cylinders: symmetry axis along body z; the thin rod along body x)",
        keys: &[
            key("type", "\"thin_disk\" | \"disk\" | \"thin_rod\" | \"sphere\" | \"box\" | \"cylinder\"", "–", "required", "", "the shape"),
            key("radius", "number", "m", "required for disks, cylinder, sphere", "", "> 0"),
            key("thickness", "number", "m", "required for `disk`", "", "≥ 0"),
            key("length", "number", "m", "required for `thin_rod`", "", "> 0"),
            key("size", "[a, b, c]", "m", "required for `box`", "", "edges along body x, y, z"),
            key("height", "number", "m", "required for `cylinder`", "", "> 0"),
        ],
    },
    Table {
        header: "[[body.point_mass]]",
        about: "a point mass rigidly attached; mass, C and the inertia are then the whole body's (parallel axes)",
        keys: &[
            key("mass", "number", "kg", "required", "", "> 0"),
            key("at", "[x, y, z]", "m", "[0, 0, 0]", FROM_REFERENCE, "where the mass sits"),
        ],
    },
    Table {
        header: "[[body.rotor]]",
        about: "a wheel spinning inside the body about an axis fixed in it (free motion or a pivot only)",
        keys: &[
            key("name", "string", "–", "rotor0, rotor1, …", "", "the prefix of its columns: letters, digits, `_`; unique"),
            key("axis", "[x, y, z]", "–", "required", "", "spin axis in body axes (normalised, not zero)"),
            key("inertia", "number", "kg·m²", "required", "", "J about the spin axis, > 0; `[body]` already holds J a aᵀ (wheels locked)"),
            key("spin", "number", "rad/s", "0", "", "Ω at t = 0, relative to the body"),
            key("spin_accel", "number", "rad/s²", "none", "", "Ω(t) = spin + spin_accel·t prescribed; the motor torque is an output"),
            key("torque", "number", "N·m", "none", "", "instead of `spin_accel`: the motor torque on the wheel (the body feels its opposite); neither: Ω stays constant"),
            key("profile", "\"constant\" | \"sine\" | \"step\"", "–", "\"constant\"", "", "the motor torque's profile, as a torque effect's"),
            key("freq_hz", "number", "Hz", "required for `sine`", "", "≥ 0"),
            key("phase_deg", "number", "deg", "0", "", "`sine` only"),
            key("t_on", "number", "s", "0", "", "`step` only"),
            key("t_off", "number", "s", "never", "", "`step` only; > t_on"),
            key("at", "[x, y, z]", "m", "[0, 0, 0]", FROM_REFERENCE, "the wheel's centre"),
            key("imbalance_static_gmm", "number", "g·mm", "0", "", "≥ 0: U_s = m·e, a force U_s Ω² at `at` turning with the wheel"),
            key("imbalance_dynamic_gmm2", "number", "g·mm²", "0", "", "≥ 0: U_d, a couple U_d Ω² turning with the wheel"),
        ],
    },
    Table {
        header: "[motion]",
        about: "absent: free rotation",
        keys: &[
            key("type", "\"free\" | \"fixed_axis\" | \"hinge\"", "–", "required in the table", "", "free (no other keys), a prescribed rotation about a fixed axis, or a hinge (θ from the effects)"),
            key("axis", "[x, y, z]", "–", "`axis` or `tilt_deg` required", "", "the fixed axis's direction in body axes, normalised; not zero"),
            key("tilt_deg", "number", "deg", "none", "", "instead of `axis`: axis = (0, −sin tilt, cos tilt)"),
            key("rate", "number", "rad/s", "0", "", "θ̇ at t = 0"),
            key("rate_rpm", "number", "rpm", "none", "", "instead of `rate`: rate = rate_rpm · 2π/60"),
            key("accel", "number", "rad/s²", "0", "", "constant θ̈; fixed axis only"),
            key("point", "[x, y, z]", "m", "[0, 0, 0]", FROM_REFERENCE, "a point of the axis: the moment center"),
            key("angle_deg", "number", "deg", "0", "", "hinge only: θ at t = 0"),
            key("bearings", "[a, b]", "m", "none", "from `point`, along the axis", "positions of bearings A and B, a ≠ b; adds the `R_*` columns"),
            key("axis_in_space", "[x, y, z]", "–", "none", "", "the axis's direction in space axes: the attitude at t = 0 puts the body axis on it (instead of `initial.attitude`)"),
            key("carrier", "inline table", "–", "none", "", "the axis turns with a carrier: `[motion.carrier]`"),
        ],
    },
    Table {
        header: "[motion.carrier]",
        about: "a carrier turning the axis, its point and bearings at Ω_c = rate·p(t), space axes, about the axis point",
        keys: &[
            key("rate", "[x, y, z]", "rad/s", "required", "", "space axes"),
            key("profile", "\"constant\" | \"sine\"", "–", "\"constant\"", "", "p = 1, or sin(2π freq_hz t + phase_deg)"),
            key("freq_hz", "number", "Hz", "required for `sine`", "", "≥ 0"),
            key("phase_deg", "number", "deg", "0", "", "`sine` only"),
        ],
    },
    Table {
        header: "[initial]",
        about: "the state at t = 0",
        keys: &[
            key("omega", "[x, y, z]", "rad/s", "[0, 0, 0]", "", "ω(0) in body axes; free motion only"),
            key("attitude", "[w, x, y, z]", "1", "[1, 0, 0, 0]", "", "body → space quaternion, normalised; not zero"),
            key("attitude_euler_deg", "[z, y, x]", "deg", "none", "", "instead of `attitude`: intrinsic z-y′-x″ angles, R = R_z R_y′ R_x″"),
        ],
    },
    Table {
        header: "[[effect]]",
        about: "a moment on the body; any number, at most one gravity",
        keys: &[
            key("type", "\"torque\" | \"gravity\" | \"damping\" | \"torque_table\"", "–", "required", "", "the effect"),
            key("frame", "\"body\" | \"space\"", "–", "\"body\"", "", "torque and torque_table: the axes of the moment"),
            key("value", "[x, y, z]", "N·m", "required for `torque`", "", "the torque (amplitude for `sine`)"),
            key("profile", "\"constant\" | \"sine\" | \"step\"", "–", "\"constant\"", "", "torque: value, value·sin(2π freq_hz t + phase), or value for t_on ≤ t < t_off"),
            key("freq_hz", "number", "Hz", "required for `sine`", "", "≥ 0"),
            key("phase_deg", "number", "deg", "0", "", "`sine` only"),
            key("t_on", "number", "s", "0", "", "`step` only"),
            key("t_off", "number", "s", "never", "", "`step` only; > t_on"),
            key("g", "[x, y, z]", "m/s²", "[0, 0, -9.81]", "", "gravity: uniform, space axes, acting at C"),
            key("pivot", "[x, y, z]", "m", "required for free motion", FROM_REFERENCE, "gravity: the fixed point, which becomes the moment center (an error with a fixed axis or hinge)"),
            key("c", "number", "N·m·s", "required for `damping`", "", "viscous M = −c·ω, ≥ 0"),
            key("file", "path", "–", "required for `torque_table`", "", "CSV with header t,M_x,M_y,M_z (s, N·m), relative to the scene file; zero outside its rows"),
            key("interpolation", "\"linear\" | \"cubic\"", "–", "\"linear\"", "", "torque_table: between rows (cubic: the natural spline)"),
        ],
    },
    Table {
        header: "[[event]]",
        about: "a moment located between the rows on the continuous solution",
        keys: &[
            key("name", "string", "–", "required", "", "letters, digits, `_`; unique"),
            key("when", "string", "–", "required", "", "a CSV column of this run, or `|X|` for the norm of X_s_x..z"),
            key("crosses", "number", "the column's", "one of `crosses` / `extremum`", "", "a crossing of this value"),
            key("direction", "\"up\" | \"down\" | \"both\"", "–", "\"both\"", "", "with `crosses`"),
            key("extremum", "\"max\" | \"min\"", "–", "one of `crosses` / `extremum`", "", "every local extremum"),
            key("stop", "bool", "–", "false", "", "true: the run ends at the first occurrence"),
        ],
    },
    Table {
        header: "[solver]",
        about: "the integration; `run --method --frame --backend --rtol --atol --dt --t-end` override it",
        keys: &[
            key("method", "\"rk4\" | \"split2\" | \"split4\" | \"dopri5\" | \"dop853\" | \"exact\"", "–", "\"dop853\"", "", "fixed step (`dt`), adaptive, or the torque-free closed form"),
            key("frame", "\"body\" | \"space\"", "–", "\"body\"", "", "which form of Euler's equation is integrated"),
            key("backend", "\"own\" | \"ode_solvers\"", "–", "\"own\"", "", "the Runge–Kutta implementation"),
            key("rtol", "number", "1", "1e-10", "", "adaptive methods, in [1e-14, 1)"),
            key("atol", "number", "as the state", "1e-12", "", "adaptive methods, > 0"),
            key("dt", "number", "s", "1e-3", "", "fixed-step methods, > 0"),
            key("t_end", "number", "s", "required", "", "≥ 0"),
        ],
    },
    Table {
        header: "[output]",
        about: "the rows; `run --every` overrides it",
        keys: &[key("every", "number", "s", "required", "", "> 0: rows at t = k·every and at t_end")],
    },
    Table {
        header: "[compare]",
        about: "`eulerdyn compare`'s tolerance",
        keys: &[key("tolerance", "number", "as the quantity", "1e-8", "", "largest accepted difference, > 0")],
    },
];
