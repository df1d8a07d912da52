//! What the page draws besides the rows: the body's shape, its point masses, the fixed axis and the bearings, the
//! inertia for the polhode — all read from the run's sidecar (`RUN.csv.meta.json`), whose `scene.spec` is the scene
//! as the run simulated it. Without a usable sidecar the page draws what the CSV allows, and says what is missing.
//!
//! Every position is given in body axes from the moment center O (C, the gravity pivot, or the fixed axis's
//! point), which the page puts at the origin of space.

use std::path::Path;

use nalgebra::{Matrix3, Vector3};
use serde_json::{Value, json};

use crate::body::Principal;
use crate::effects::Effect;
use crate::output::sidecar::{Sidecar, sidecar_path};
use crate::scene::{Distribution, InertiaSpec, Overrides, SceneSpec, ShapeSpec};

/// The page's picture of the body and its supports, and notes on what could not be drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// The JSON object the page's script reads (`body`, `point_masses`, `axis_b`, `bearings`, `inertia_p`, …).
    pub json: Value,
    /// What is missing or approximate, in words (printed on stderr and shown in the page).
    pub notes: Vec<String>,
}

/// The geometry of the run whose CSV is `csv`, from its sidecar's scene; when the sidecar is missing or
/// unusable, an unknown body with a note saying why.
pub fn read_geometry(csv: &Path) -> Geometry {
    let name = sidecar_path(csv);
    let sidecar = match std::fs::exists(&name) {
        Ok(false) => {
            return Geometry::unknown(format!(
                "there is no sidecar {}: the body's shape, inertia and supports are unknown, so the body is \
                 drawn as a unit cube (not to scale), with no fixed axis, bearings or polhode; the vectors and \
                 the attitude are the CSV's",
                name.display()
            ));
        }
        _ => Sidecar::read(csv),
    };
    match sidecar.and_then(|sidecar| geometry_of_sidecar(&sidecar)) {
        Ok(geometry) => geometry,
        Err(problem) => Geometry::unknown(format!(
            "{}: {problem}; the body is drawn as a unit cube (not to scale), with no fixed axis, bearings or polhode",
            name.display()
        )),
    }
}

impl Geometry {
    /// An unknown body (drawn as a unit cube), with `note` saying why.
    pub fn unknown(note: String) -> Geometry {
        Geometry {
            json: json!({ "source": "csv", "body": { "kind": "unknown" }, "point_masses": [] }),
            notes: vec![note],
        }
    }
}

/// The geometry from the sidecar's scene (as simulated).
fn geometry_of_sidecar(sidecar: &Sidecar) -> Result<Geometry, String> {
    let spec = &sidecar.scene.spec;
    let scene = spec.build_with(&Overrides::default()).map_err(|e| {
        format!(
            "the sidecar's scene is not valid ({}: {})",
            e.key, e.problem
        )
    })?;
    let (rho_c_b, inertia_o_b) = scene.motion.about_moment_center();
    let axis = scene.motion.axis();
    // The reference origin (shape center) from O: from C it is −center_b, and C is at ρ_C from O.
    let reference_o = rho_c_b - scene.center_b;
    let mut notes = Vec::new();
    let body = body_json(spec, &reference_o, &mut notes);
    let point_masses: Vec<Value> = spec
        .body
        .point_mass
        .iter()
        .map(|p| {
            let at = Vector3::from(p.at) + reference_o;
            json!({ "mass": p.mass, "at": vec3(&at) })
        })
        .collect();
    let principal = Principal::of(&inertia_o_b);
    let rotors = rotors_json(spec, &reference_o);
    let moving_masses = moving_masses_json(spec);
    let motion = &sidecar.scene.motion;
    let units: serde_json::Map<String, Value> = sidecar
        .columns
        .iter()
        .map(|c| (c.name.clone(), Value::from(c.unit.clone())))
        .collect();
    Ok(Geometry {
        json: json!({
            "source": "sidecar",
            "name": scene.name,
            "description": scene.description,
            "motion": motion,
            "effects": scene.effects.iter().map(|e| e.kind()).collect::<Vec<_>>(),
            "gravity_s": gravity_s(&scene.effects).map(|g| vec3(&g)),
            "orbit": scene.orbit.map(|o| json!({
                "mean_motion": o.mean_motion(),
                "inclination": o.inclination(),
                "raan": o.raan(),
                "arg_lat0": o.arg_lat0(),
            })),
            "body": body,
            "point_masses": point_masses,
            "rotors": rotors,
            "moving_masses": moving_masses,
            "reference_o": vec3(&reference_o),
            "mass_center": vec3(&rho_c_b),
            "axis_b": axis.map(|a| vec3(a.axis_b())),
            "bearings": axis.and_then(|a| a.bearings()).map(|b| [b.a, b.b]),
            "inertia_p": vec3(&principal.moments),
            "axes_p_b": columns(principal.axes_b.matrix()),
            "units": units,
        }),
        notes,
    })
}

/// The wheels (`[[body.rotor]]`) as the page draws them: `name` (the prefix of its columns, `rotorK` when absent,
/// as validation names it), `axis_b` (its unit spin axis, body axes), `at` (its centre in body axes from O) and
/// `inertia` (J, kg·m²).
fn rotors_json(spec: &SceneSpec, reference_o: &Vector3<f64>) -> Vec<Value> {
    (spec.body.rotor.iter().enumerate())
        .map(|(k, r)| {
            let axis_b = Vector3::from(r.axis).normalize();
            let at = Vector3::from(r.at) + reference_o;
            json!({
                "name": r.name.clone().unwrap_or_else(|| format!("rotor{k}")),
                "axis_b": vec3(&axis_b),
                "at": vec3(&at),
                "inertia": r.inertia,
            })
        })
        .collect()
}

/// The moving masses (`[[body.moving_mass]]`): each one's name, whose columns `<name>_x`, `<name>_y`, `<name>_z`
/// hold its position from the reference origin (drawn from O at `reference_o`), and its mass.
fn moving_masses_json(spec: &SceneSpec) -> Vec<Value> {
    (spec.body.shape_change.moving_mass.iter().enumerate())
        .map(|(k, m)| {
            let name = m.name.clone().unwrap_or_else(|| format!("mass{k}"));
            json!({ "name": name, "mass": m.mass })
        })
        .collect()
}

impl Geometry {
    /// The names of the moving masses whose positions the page draws.
    pub fn moving_mass_names(&self) -> Vec<String> {
        let masses = self.json["moving_masses"].as_array();
        (masses.into_iter().flatten())
            .filter_map(|m| m["name"].as_str().map(String::from))
            .collect()
    }
}

/// Thin parts of a body are drawn at least this fraction of its longest dimension thick: a thin rod or a thin disk
/// (no thickness at all) or a flat box would otherwise be a line or a sheet, lost behind the axes and the arrows.
pub const MIN_DRAWN_THICKNESS: f64 = 0.05;

/// The body's shape as the page draws it: its kind, dimensions (m), center (the reference origin, from O) and
/// `min_drawn_thickness` (m, [`MIN_DRAWN_THICKNESS`] of its longest dimension), with `drawn_thicker` saying so
/// (for the legend; not a warning) when a part is drawn thicker than it is.
fn body_json(spec: &SceneSpec, reference_o: &Vector3<f64>, notes: &mut Vec<String>) -> Value {
    let mut body = shape_or_inertia_box(spec, reference_o, notes);
    if let Some((thinnest, longest)) = extent(&body) {
        let min = MIN_DRAWN_THICKNESS * longest;
        if thinnest < min {
            body["drawn_thicker"] = json!(format!(
                "drawn at least {min:.3} m thick ({:.0} % of its longest dimension, {longest:.3} m) so that it \
                 shows; its thinnest dimension is {thinnest:.3} m",
                MIN_DRAWN_THICKNESS * 100.0
            ));
        }
        body["min_drawn_thickness"] = json!(min);
    }
    body
}

/// The thinnest and the longest dimension (m) of a body as [`body_json`] describes it, if its kind is known.
fn extent(body: &Value) -> Option<(f64, f64)> {
    let get = |key: &str| body.get(key).and_then(Value::as_f64);
    let pair = |a: f64, b: f64| Some((a.min(b), a.max(b)));
    match body.get("kind")?.as_str()? {
        "thin_rod" => Some((0.0, get("length")?)),
        "thin_disk" => Some((0.0, 2.0 * get("radius")?)),
        "disk" => pair(get("thickness")?, 2.0 * get("radius")?),
        "cylinder" => pair(get("height")?, 2.0 * get("radius")?),
        "sphere" => pair(2.0 * get("radius")?, 2.0 * get("radius")?),
        "box" | "inertia_box" => {
            let edges: Vec<f64> = body
                .get("size")?
                .as_array()?
                .iter()
                .filter_map(Value::as_f64)
                .collect();
            let min = edges.iter().cloned().fold(f64::INFINITY, f64::min);
            let max = edges.iter().cloned().fold(0.0, f64::max);
            (edges.len() == 3).then_some((min, max))
        }
        _ => None,
    }
}

/// The body's shape from the scene file, or, for a body given by its inertia, the box of equal principal moments
/// turned to its principal axes; centered at the reference origin (from O).
fn shape_or_inertia_box(
    spec: &SceneSpec,
    reference_o: &Vector3<f64>,
    notes: &mut Vec<String>,
) -> Value {
    let center = vec3(reference_o);
    let mass = spec.body.mass;
    let inertia = match spec.body.distribution {
        Distribution::Shape(shape) => return shape_json(&shape, json!(center)),
        Distribution::Inertia(InertiaSpec::Principal(m)) => {
            Matrix3::from_diagonal(&Vector3::from(m))
        }
        Distribution::Inertia(InertiaSpec::Full(rows)) => Matrix3::from_fn(|i, j| rows[i][j]),
    };
    let principal = Principal::of(&inertia);
    let size = equal_moment_box(mass, &principal.moments);
    notes.push(format!(
        "the body is given by its inertia only: drawn as the uniform box of the same mass and principal moments \
         ({:.4} x {:.4} x {:.4} m along its principal axes)",
        size[0], size[1], size[2]
    ));
    json!({
        "kind": "inertia_box",
        "size": size,
        "center": center,
        "axes_b": columns(principal.axes_b.matrix()),
    })
}

/// A shape from the scene file (`kind`: its `type`, and its dimensions), with its center.
fn shape_json(shape: &ShapeSpec, center: Value) -> Value {
    let mut value = serde_json::to_value(shape).unwrap_or_else(|_| json!({}));
    if let Value::Object(map) = &mut value {
        let kind = map.remove("type").unwrap_or(Value::Null);
        map.insert("kind".into(), kind);
        map.insert("center".into(), center);
    }
    value
}

/// The edges (a, b, c) of the uniform box of mass `m` whose principal moments are `moments`:
/// I₁ = m(b² + c²)/12 and cyclically, so a² = 6(I₂ + I₃ − I₁)/m. An edge the moments make zero or negative (a
/// flat or thin body) is drawn at 2 % of the longest.
pub fn equal_moment_box(m: f64, moments: &Vector3<f64>) -> [f64; 3] {
    let [i1, i2, i3] = [moments[0], moments[1], moments[2]];
    let squares = [i2 + i3 - i1, i1 + i3 - i2, i1 + i2 - i3].map(|s| 6.0 * s / m);
    let edges = squares.map(|s| s.max(0.0).sqrt());
    let longest = edges.iter().cloned().fold(0.0, f64::max).max(1e-9);
    edges.map(|e| e.max(0.02 * longest))
}

/// Gravity's g (space axes, m/s²) when the scene has it: the page draws −g up.
fn gravity_s(effects: &[Effect]) -> Option<Vector3<f64>> {
    (effects.iter().filter_map(Effect::gravity))
        .map(|(g_s, _)| g_s)
        .find(|g_s| g_s.norm() > 0.0)
}

/// `[x, y, z]`.
fn vec3(v: &Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

/// The columns of `m`, each `[x, y, z]`.
fn columns(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|j| [m[(0, j)], m[(1, j)], m[(2, j)]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_equal_moment_box_has_the_given_principal_moments() {
        let m = 2.0;
        let moments = Vector3::new(1.0, 2.0, 2.5);
        let [a, b, c] = equal_moment_box(m, &moments);
        let back = [
            m * (b * b + c * c) / 12.0,
            m * (a * a + c * c) / 12.0,
            m * (a * a + b * b) / 12.0,
        ];
        for k in 0..3 {
            assert!((back[k] - moments[k]).abs() < 1e-12, "{back:?}");
        }
    }

    /// A sidecar whose scene is `scene_text`.
    fn sidecar(scene_text: &str) -> Sidecar {
        let spec = crate::scene::parse_spec(Path::new("s.toml"), scene_text).expect("a scene");
        let scene = spec.build().expect("a valid scene");
        let report = crate::simulate::RunReport::default();
        Sidecar::of_run(&scene, &report, &[])
    }

    #[test]
    fn positions_are_from_the_moment_center_the_pivot_here() {
        // The heavy top: the pivot 0.05 m below C on the symmetry axis, so C is 0.05 m above O.
        let text = "[body]\nmass = 0.5\nshape = { type = \"cylinder\", radius = 0.04, height = 0.02 }\n\
                    [initial]\nomega = [0.0, 0.0, 150.0]\n[[effect]]\ntype = \"gravity\"\ng = [0.0, 0.0, -9.81]\n\
                    pivot = [0.0, 0.0, -0.05]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
        let g = geometry_of_sidecar(&sidecar(text)).expect("geometry");
        assert_eq!(g.json["body"]["kind"], "cylinder");
        assert_eq!(g.json["body"]["height"], 0.02);
        assert_eq!(g.json["body"]["center"], json!([0.0, 0.0, 0.05]));
        assert_eq!(g.json["mass_center"], json!([0.0, 0.0, 0.05]));
        assert_eq!(g.json["effects"], json!(["gravity"]));
        // The inertia about the pivot: I_C + m d² about x and y (parallel-axis theorem).
        let i_xx = 0.5 * (3.0 * 0.04f64.powi(2) + 0.02f64.powi(2)) / 12.0 + 0.5 * 0.05f64.powi(2);
        let moments = g.json["inertia_p"].as_array().expect("moments");
        assert!((moments[0].as_f64().expect("I1") - i_xx).abs() < 1e-15);
        assert!(g.notes.is_empty());
        // 2 cm tall, 8 cm across: thicker than 5 % of 8 cm, drawn as it is.
        assert!(
            (g.json["body"]["min_drawn_thickness"].as_f64().expect("min") - 0.004).abs() < 1e-15
        );
        assert!(g.json["body"].get("drawn_thicker").is_none());
    }

    #[test]
    fn a_thin_rod_is_drawn_a_twentieth_of_its_length_thick_and_the_legend_says_so() {
        let text = "[body]\nmass = 1.0\nshape = { type = \"thin_rod\", length = 1.0 }\n\
                    [motion]\ntype = \"fixed_axis\"\naxis = [0.0, 0.0, 1.0]\nrate = 1.0\n\
                    [solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
        let g = geometry_of_sidecar(&sidecar(text)).expect("geometry");
        assert_eq!(g.json["body"]["min_drawn_thickness"], 0.05);
        let said = g.json["body"]["drawn_thicker"]
            .as_str()
            .expect("a legend text");
        assert!(
            said.contains("at least 0.050 m thick (5 % of its longest dimension, 1.000 m)"),
            "{said}"
        );
        assert!(g.notes.is_empty(), "not a warning: {:?}", g.notes);
    }

    #[test]
    fn wheels_are_named_by_their_columns_with_unit_axes_placed_from_the_moment_center() {
        // A 1 kg sphere (C at its center, O = C for free motion) with an unnamed wheel on a tilted axis at x = 0.2 m,
        // and a named one at the center.
        let text = "[body]\nmass = 1.0\nshape = { type = \"sphere\", radius = 0.1 }\n\
                    [[body.rotor]]\naxis = [3.0, 0.0, 4.0]\ninertia = 0.001\nspin = 10.0\nat = [0.2, 0.0, 0.0]\n\
                    [[body.rotor]]\nname = \"w\"\naxis = [0.0, 2.0, 0.0]\ninertia = 0.002\n\
                    [solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
        let g = geometry_of_sidecar(&sidecar(text)).expect("geometry");
        let rotors = g.json["rotors"].as_array().expect("rotors");
        assert_eq!(rotors.len(), 2);
        assert_eq!(rotors[0]["name"], "rotor0");
        assert_eq!(rotors[0]["axis_b"], json!([0.6, 0.0, 0.8]));
        assert_eq!(rotors[0]["at"], json!([0.2, 0.0, 0.0]));
        assert_eq!(rotors[1]["name"], "w");
        assert_eq!(rotors[1]["axis_b"], json!([0.0, 1.0, 0.0]));
        assert_eq!(rotors[1]["inertia"], 0.002);
        // Without rotors, none.
        let plain = "[body]\nmass = 1.0\nshape = { type = \"sphere\", radius = 0.1 }\n\
                     [solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
        let g = geometry_of_sidecar(&sidecar(plain)).expect("geometry");
        assert_eq!(g.json["rotors"], json!([]));
    }

    #[test]
    fn point_masses_are_placed_from_the_moment_center() {
        // A 1 kg sphere with 1 kg at x = 0.2 m from its center: C is at x = 0.1, and O = C for free motion.
        let text = "[body]\nmass = 1.0\nshape = { type = \"sphere\", radius = 0.1 }\n\
                    [[body.point_mass]]\nmass = 1.0\nat = [0.2, 0.0, 0.0]\n\
                    [initial]\nomega = [0.0, 0.0, 1.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
        let g = geometry_of_sidecar(&sidecar(text)).expect("geometry");
        let close = |v: &Value, want: [f64; 3]| {
            (0..3).all(|k| (v[k].as_f64().expect("a number") - want[k]).abs() < 1e-15)
        };
        assert!(
            close(&g.json["body"]["center"], [-0.1, 0.0, 0.0]),
            "{}",
            g.json
        );
        assert!(
            close(&g.json["point_masses"][0]["at"], [0.1, 0.0, 0.0]),
            "{}",
            g.json
        );
    }

    #[test]
    fn a_sidecar_whose_scene_is_invalid_is_named_with_the_key() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let csv = dir.path().join("x.csv");
        let mut bad = sidecar(
            "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n",
        );
        bad.scene.spec.body.mass = -1.0;
        std::fs::write(sidecar_path(&csv), bad.to_json()).expect("written");
        let g = read_geometry(&csv);
        assert_eq!(g.json["body"]["kind"], "unknown");
        assert!(
            g.notes[0].contains("x.csv.meta.json: the sidecar's scene is not valid (body.mass"),
            "{:?}",
            g.notes
        );
    }

    #[test]
    fn a_missing_sidecar_gives_an_unknown_body_and_a_note_naming_it() {
        let g = read_geometry(Path::new("/nonexistent/run.csv"));
        assert_eq!(g.json["body"]["kind"], "unknown");
        assert!(g.notes[0].contains("there is no sidecar /nonexistent/run.csv.meta.json"));
    }
}
