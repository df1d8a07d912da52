//! A capability lives in its folder (ARCHITECTURE.md, "Where a new thing goes"): outside it, the code of src/ and
//! core/src/ does not name what only the capability knows, except in the registration lines listed here. Comments
//! and test modules are not code for this purpose (a doc comment may say "carrier"; a test may build one).

use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`, recursively, in a stable order.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            files.extend(rust_files(&path));
        } else if path.extension().is_some_and(|x| x == "rs") {
            files.push(path);
        }
    }
    files
}

/// The code of a source file: its lines before `#[cfg(test)]`, without comment lines.
fn code(path: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (text.lines())
        .take_while(|l| l.trim() != "#[cfg(test)]")
        .filter(|l| !l.trim_start().starts_with("//"))
        .map(str::to_string)
        .collect()
}

/// Whether `line` names `name`: where `name` is an identifier, where no identifier character comes before it (the
/// type `Friction`, not the panel `WheelFriction`); else wherever it appears (`Drive::`, `.control`).
fn names_in(line: &str, name: &str) -> bool {
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    if !name.chars().all(ident) {
        return line.contains(name);
    }
    (line.match_indices(name)).any(|(at, _)| !line[..at].chars().next_back().is_some_and(ident))
}

/// The places (`file:line: text`) outside `folder` whose code names one of `names`, except the lines of
/// `registrations` (a file, and a text its line contains).
fn named_outside(folder: &str, names: &[&str], registrations: &[(&str, &str)]) -> Vec<String> {
    let mut found = Vec::new();
    for root in ["src", "core/src"] {
        let src = Path::new(env!("CARGO_MANIFEST_DIR")).join(root);
        for path in rust_files(&src) {
            let relative = path.strip_prefix(&src).expect("under the root");
            let relative = relative.to_string_lossy().replace('\\', "/");
            if relative.starts_with(folder) {
                continue;
            }
            for (n, line) in code(&path).iter().enumerate() {
                let registered = (registrations.iter())
                    .any(|(file, text)| relative == *file && line.contains(text));
                if !registered && names.iter().any(|name| names_in(line, name)) {
                    found.push(format!("{root}/{relative}:{}: {}", n + 1, line.trim()));
                }
            }
        }
    }
    found
}

#[test]
fn the_wheels_control_is_named_only_in_its_folder() {
    let names = [
        "WheelControl",
        "WheelKeys",
        "FrictionKeys",
        "StribeckKeys",
        "WheelMode",
        "Friction",
        "WheelTorqueLaw",
        "WheelInputs",
        "wheels::solve",
        "Drive::",
        ".control",
        "max_torque",
        "max_speed",
        "RotorRows",
        "MAX_ROTORS",
    ];
    let outside = named_outside("wheels/", &names, &[]);
    assert!(
        outside.is_empty(),
        "outside core/src/wheels/:\n{}",
        outside.join("\n")
    );
}

#[test]
fn the_wheels_are_registered_in_the_listed_lines_only() {
    let names = ["RotorFile", "RotorSpec", "validate_rotors"];
    let registrations = [
        ("scene/spec/file_form.rs", "use crate::wheels::RotorSpec;"),
        ("scene/spec/file_form.rs", "pub rotor: Vec<RotorSpec>,"),
        ("scene/spec/body.rs", "use crate::wheels::RotorSpec;"),
        (
            "scene/spec/body.rs",
            "pub fn with_rotor(mut self, rotor: RotorSpec)",
        ),
        (
            "scene/spec/mod.rs",
            "pub use crate::wheels::{RotorDrive, RotorSpec};",
        ),
        ("scene/mod.rs", "RotorSpec"),
        (
            "scene/validate/motion.rs",
            "crate::wheels::validate_rotors(&doc.body.rotor",
        ),
    ];
    let outside = named_outside("wheels/", &names, &registrations);
    assert!(
        outside.is_empty(),
        "outside core/src/wheels/:\n{}",
        outside.join("\n")
    );
}

#[test]
fn the_carrier_is_named_only_in_its_folder_and_its_part_line() {
    let registrations = [
        ("motion/mod.rs", "pub mod carrier;"),
        ("motion/keys.rs", "use super::carrier::spec::CarrierSpec;"),
        ("motion/keys.rs", "use super::carrier::keys::CarrierFile;"),
        ("motion/keys.rs", "part = CarrierSpec"),
        ("motion/keys.rs", "carrier: Option<CarrierFile>,"),
        (
            "motion/spec.rs",
            "pub use super::carrier::spec::{CarrierSpec, VehicleSpec};",
        ),
        ("motion/spec.rs", "CarrierSpec"),
        ("scene/spec/mod.rs", "CarrierSpec"),
        ("scene/spec/mod.rs", "VehicleSpec"),
        ("scene/mod.rs", "CarrierSpec"),
        ("scene/mod.rs", "VehicleSpec"),
    ];
    let outside = named_outside(
        "motion/carrier/",
        &["Carrier", "carrier::", "Vehicle"],
        &registrations,
    );
    assert!(
        outside.is_empty(),
        "outside core/src/motion/carrier/:\n{}",
        outside.join("\n")
    );
}

#[test]
fn the_effects_and_events_tables_are_named_only_in_their_folders_and_registrations() {
    let registrations = [
        ("scene/spec/file_form.rs", "use crate::effects::EffectSpec;"),
        ("scene/spec/file_form.rs", "use crate::events::EventSpec;"),
        ("scene/spec/file_form.rs", "pub effect: Vec<EffectSpec>,"),
        ("scene/spec/file_form.rs", "pub event: Vec<EventSpec>,"),
        ("scene/spec/mod.rs", "pub use crate::effects::{EffectSpec,"),
        (
            "scene/spec/mod.rs",
            "pub use crate::events::{ConditionSpec, Direction, EventSpec,",
        ),
        (
            "scene/spec/mod.rs",
            "pub fn with_effect(mut self, effect: impl Into<EffectSpec>)",
        ),
        (
            "scene/spec/mod.rs",
            "pub fn with_event(mut self, event: EventSpec)",
        ),
        ("scene/mod.rs", "EffectSpec, EventSpec,"),
        ("lib.rs", "EffectSpec,"),
        ("scene/validate/mod.rs", "crate::effects::validate_effects("),
        (
            "scene/validate/mod.rs",
            "crate::events::validate_events(&doc.event",
        ),
    ];
    for (folder, names) in [
        (
            "effects/",
            ["EffectFile", "EffectKind", "EffectSpec", "validate_effects"],
        ),
        (
            "events/",
            [
                "EventFile",
                "EventSpec",
                "Quantity::parse",
                "validate_events",
            ],
        ),
    ] {
        let outside = named_outside(folder, &names, &registrations);
        assert!(
            outside.is_empty(),
            "outside {folder}:\n{}",
            outside.join("\n")
        );
    }
}

#[test]
fn the_motion_table_is_named_only_in_its_folder_and_its_registration() {
    let registrations = [
        (
            "scene/spec/file_form.rs",
            "use crate::motion::keys::MotionFile;",
        ),
        ("scene/spec/file_form.rs", "opt motion: MotionFile"),
    ];
    let outside = named_outside("motion/", &["MotionFile", "motion::keys"], &registrations);
    assert!(
        outside.is_empty(),
        "outside core/src/motion/:\n{}",
        outside.join("\n")
    );
}

#[test]
fn each_effect_kind_is_named_only_in_its_folder_and_the_registry() {
    // A kind is its folder plus its lines in `effects/kinds.rs` (and the re-exports of the effects' and the scene's
    // public names); the rest of the library asks an effect through `Effect`'s queries.
    let registrations = [
        ("effects/kinds.rs", ""),
        ("effects/spec_builders.rs", ""),
        ("effects/mod.rs", "pub use "),
        ("scene/spec/mod.rs", "pub use crate::effects::{EffectSpec,"),
        ("scene/mod.rs", "Spec,"),
        ("lib.rs", "Spec,"),
    ];
    for (folder, names) in [
        // `TorqueGiven` is what the query `Effect::torque` answers: the closed forms and the suite read it.
        ("effects/torque/", &["TorqueKeys", "TorqueSpec"][..]),
        ("effects/gravity/", &["GravityKeys", "GravitySpec"]),
        (
            "effects/damping/",
            &["DampingKeys", "DampingSpec", "Damping"],
        ),
        (
            "effects/torque_table/",
            &["TorqueTableKeys", "TorqueTableSpec", "TabulatedTorque"],
        ),
        (
            "effects/gravity_gradient/",
            &["GravityGradientSpec", "GravityGradient"],
        ),
        (
            "effects/magnetic/",
            &["MagneticKeys", "MagneticSpec", "MagneticDipole"],
        ),
        ("effects/b_dot/", &["BDotKeys", "BDotSpec", "BDot"]),
    ] {
        let outside = named_outside(folder, names, &registrations);
        assert!(
            outside.is_empty(),
            "outside core/src/{folder}:\n{}",
            outside.join("\n")
        );
    }
}

#[test]
fn the_fifth_round_s_effect_kinds_are_one_line_each_in_the_registry() {
    // An effect kind is its folder plus one line of `effect_kinds!` (ARCHITECTURE.md, "An effect kind"); the
    // registry's `use` of the folder's two types is the import that line needs.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("core/src/effects/kinds.rs");
    let code = code(&path);
    for (spec, effect) in [
        ("GravityGradientSpec", "GravityGradient"),
        ("MagneticSpec", "MagneticDipole"),
        ("BDotSpec", "BDot"),
    ] {
        let lines: Vec<&String> = (code.iter())
            .filter(|l| names_in(l, spec) || names_in(l, effect))
            .collect();
        let registered = |l: &&String| l.contains(&format!(": {spec} => {effect},"));
        let imported = |l: &&String| l.trim_start().starts_with("use super::");
        assert!(
            lines.len() == 2 && lines.iter().any(registered) && lines.iter().any(imported),
            "{spec}, {effect} in effects/kinds.rs beyond its `use` and registry line:\n{lines:#?}"
        );
    }
}

#[test]
fn the_shape_change_is_named_only_in_its_folder_and_its_registrations() {
    // A body attribute is its folder plus its field in `[body]` and its line in the registry `scene/attributes.rs`;
    // every other question goes through the doors of `motion::attribute`: `AttributeSpec` (its validation),
    // `BodyAttribute` (facts, method rules, `check`, columns) and `AttributeDrive` (the run).
    let registrations = [
        ("lib.rs", "pub mod shape_change;"),
        // eulerdyn re-exports each of the core's modules.
        ("lib.rs", " shape_change, simulate,"),
        (
            "scene/spec/file_form.rs",
            "use crate::shape_change::{ShapeChangeKeys, ShapeChangeSpec};",
        ),
        ("scene/spec/file_form.rs", "flatten = ShapeChangeKeys"),
        (
            "scene/spec/file_form.rs",
            "pub shape_change: ShapeChangeSpec,",
        ),
        (
            "scene/attributes.rs",
            "use crate::shape_change::ShapeChange;",
        ),
        (
            "scene/attributes.rs",
            "ShapeChange(Arc<ShapeChange>) = shape_change,",
        ),
        // The 3D page draws the moving masses of the scene as the sidecar keeps it.
        (
            "output/view/geometry.rs",
            "(spec.body.shape_change.moving_mass.iter().enumerate())",
        ),
    ];
    let outside = named_outside(
        "shape_change/",
        &[
            "shape_change",
            "ShapeChange",
            "ChangingForm",
            "ChangingSplit",
            "MovingMass",
            "InertiaHistory",
        ],
        &registrations,
    );
    assert!(
        outside.is_empty(),
        "outside core/src/shape_change/:\n{}",
        outside.join("\n")
    );
}
