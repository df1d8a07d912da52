//! The body's keys its declaration cannot read by itself (`file_form.rs` reads and writes the rest): `shape` or
//! `inertia` as the body's [`Distribution`], one of them required. Each failure names the key (the TOML front end adds its line); the values themselves
//! (finite, in range) are validation's ([`SceneSpec::build`](super::SceneSpec::build)).

use super::file_form::DistributionKeys;
use super::{Distribution, ShapeSpec};
use crate::keys::{Checked, Group, KeyPath, Part, invalid};

/// `shape` (read as a [`ShapeSpec`]) or `inertia`; one of them is required.
impl Group<DistributionKeys> for Distribution {
    fn read(file: &DistributionKeys, at: &KeyPath) -> Checked<Self> {
        match (&file.shape, file.inertia) {
            (None, None) => invalid(
                at.clone(),
                "the body needs `shape` (e.g. { type = \"thin_disk\", radius = 0.3 }) or `inertia` ([I1, I2, I3] or a 3x3 tensor)",
            ),
            (Some(s), _) => Ok(Distribution::Shape(ShapeSpec::read(
                s,
                &at.clone().key("shape"),
            )?)),
            (None, Some(inertia)) => Ok(Distribution::Inertia(inertia)),
        }
    }

    fn write(&self, file: &mut DistributionKeys) {
        match *self {
            Distribution::Shape(shape) => file.shape = Some(shape.write()),
            Distribution::Inertia(inertia) => file.inertia = Some(inertia),
        }
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;
    use crate::frames::Axes;
    use crate::profile::Profile;
    use crate::scene::{
        AttitudeSpec, BodySpec, CarrierSpec, Direction, EffectSpec, EventSpec, Extremum,
        FixedAxisSpec, HingeSpec, InertiaSpec, InitialSpec, MotionSpec, RateSpec, RotorDrive,
        RotorSpec, SceneSpec, TorqueSpec, TorqueTableSpec, parse_spec,
    };
    use crate::wheels::WheelKeys;

    /// Every variant of the typed scene, written as TOML by serde and read back by the scene file's reader,
    /// is the same value.
    #[test]
    fn every_variant_reads_back_as_written() {
        let shapes = [
            ShapeSpec::thin_disk(0.3),
            ShapeSpec::disk(0.3, 0.02),
            ShapeSpec::thin_rod(1.0),
            ShapeSpec::sphere(0.1),
            ShapeSpec::cuboid([0.1, 0.2, 0.3]),
            ShapeSpec::cylinder(0.1, 0.5),
        ];
        let fixed = FixedAxisSpec::tilted(30.0, 10.0).with_accel(1.0);
        let mut rpm = HingeSpec::new([1.0, 0.0, 0.0], 0.0).with_bearings(-0.1, 0.2);
        rpm.axis.rate = RateSpec::Rpm(3000.0);
        rpm.axis.axis_in_space = Some([0.0, 1.0, 0.0]);
        let yawing = fixed.with_carrier(CarrierSpec::constant([0.0, 0.0, 0.5]));
        let rolling = rpm.with_carrier(CarrierSpec::sine([0.2, 0.0, 0.0], 0.1, 30.0));
        let motions = [
            MotionSpec::Free,
            fixed.into(),
            rpm.into(),
            yawing.into(),
            rolling.into(),
        ];
        let torques = [
            TorqueSpec::new(Axes::Space, [1.0, 2.0, 3.0]),
            TorqueSpec::new(Axes::Body, [0.0, 0.0, 1.0]).sine(2.0, 45.0),
            TorqueSpec::new(Axes::Body, [0.0, 0.0, 1.0]).step(0.5, 1.5),
            TorqueSpec::new(Axes::Body, [0.0, 0.0, 1.0]).step(0.5, f64::INFINITY),
        ];
        let effects: Vec<EffectSpec> = (torques.into_iter().map(EffectSpec::from))
            .chain([EffectSpec::gravity([0.0, 0.0, -9.81], [0.0, 0.0, -0.1])])
            .chain([EffectSpec::standard_weight(), EffectSpec::damping(0.1)])
            .chain([TorqueTableSpec::new("t.csv")
                .in_axes(Axes::Space)
                .cubic()
                .into()])
            .collect();
        let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 100.0);
        let rotors = [
            wheel.clone().with_imbalance([0.1, 0.0, 0.0], 2.0, 50.0),
            wheel
                .clone()
                .with_name("w")
                .with_drive(RotorDrive::SpinAccel(2.0)),
            wheel.clone().with_drive(RotorDrive::Torque {
                value: 0.1,
                profile: Profile::Sine {
                    freq_hz: 1.0,
                    phase_deg: 10.0,
                },
            }),
            (wheel.clone())
                .with_drive(RotorDrive::Table("w.csv".into()))
                .with_wheel(WheelKeys {
                    max_torque: Some(0.05),
                    max_speed_rpm: Some(6000.0),
                    friction: None,
                }),
            wheel.with_drive(RotorDrive::Free),
        ];
        let events = [
            EventSpec::crossing("flip", "omega_b_y", 0.0, Direction::Down),
            EventSpec::extremum("peak", "|H_s|", Extremum::Max).stopping(),
        ];
        for (i, shape) in shapes.into_iter().enumerate() {
            let body = BodySpec::shape(1.0, shape)
                .with_point_mass(0.1, [0.1, 0.0, 0.0])
                .with_rotor(rotors[i % rotors.len()].clone());
            let mut spec = SceneSpec::new(body, 1.0, 0.1)
                .with_effect(effects[i % effects.len()].clone())
                .with_effect(effects[(i + 3) % effects.len()].clone())
                .with_event(events[i % events.len()].clone());
            spec.motion = Some(motions[i % motions.len()]);
            spec.initial = Some(InitialSpec {
                omega: Some([0.1, 0.2, 0.3]),
                attitude: Some(AttitudeSpec::EulerDeg([10.0, 20.0, 30.0])),
                ..InitialSpec::default()
            });
            let text = toml::to_string(&spec).unwrap();
            assert_eq!(parse_spec(Path::new("x.toml"), &text), Ok(spec), "{text}");
        }
        let tensor = [[2.0, -0.1, 0.0], [-0.1, 3.0, 0.0], [0.0, 0.0, 4.0]];
        let spec = SceneSpec::new(BodySpec::tensor(1.0, tensor), 1.0, 0.1).with_attitude([1.0; 4]);
        let text = toml::to_string(&spec).unwrap();
        let back = parse_spec(Path::new("x.toml"), &text).unwrap();
        assert_eq!(
            back.body.distribution,
            Distribution::Inertia(InertiaSpec::Full(tensor))
        );
        assert_eq!(back, spec);
    }

    /// A torque table's relative `file` (an effect's, a wheel's drive's) is relative to the scene file's directory:
    /// the generated reading walks the scene's parts and groups to each of them.
    #[test]
    fn relative_table_files_are_taken_in_the_scene_files_directory() {
        let text = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n\
                    [[body.rotor]]\naxis = [0.0, 0.0, 1.0]\ninertia = 0.01\ntorque_table = \"w.csv\"\n\
                    [[effect]]\ntype = \"torque_table\"\nfile = \"t.csv\"\n\
                    [solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
        let spec = parse_spec(Path::new("runs/x.toml"), text).unwrap();
        assert_eq!(
            spec.body.rotor[0].drive,
            RotorDrive::Table(Path::new("runs").join("w.csv"))
        );
        let EffectSpec::TorqueTable(table) = &spec.effect[0] else {
            panic!("{:?}", spec.effect[0]);
        };
        assert_eq!(table.file, Path::new("runs").join("t.csv"));
    }
}
