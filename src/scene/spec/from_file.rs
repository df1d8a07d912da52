//! The scene file's form ([`SceneFile`]) into the typed [`SceneSpec`] and back. Reading checks what the types
//! cannot hold: a table's `type` and the keys that type takes, keys that exclude each other and keys a type
//! requires; each failure names the key (the TOML front end adds its line). The values themselves (finite, in
//! range) are validation's ([`SceneSpec::build`]).

use super::file_form::{BodyFile, InitialFile, PointMassFile, SceneFile, ShapeFile, ShapeKind};
use super::{
    BodySpec, Distribution, EffectSpec, EventSpec, InitialSpec, MotionSpec, PointMassSpec,
    RotorSpec, SceneSpec, ShapeSpec,
};
use crate::keys::{Checked, Either, Part, invalid, required};
use crate::scene::source_map::KeyPath;

impl SceneFile {
    /// The typed scene, or the first key at fault.
    pub(in crate::scene) fn into_spec(self) -> Checked<SceneSpec> {
        Ok(SceneSpec {
            name: self.name,
            description: self.description,
            body: body(self.body)?,
            motion: (self.motion.as_ref())
                .map(|m| MotionSpec::read(m, &KeyPath::root().key("motion")))
                .transpose()?,
            initial: self.initial.map(initial).transpose()?,
            effect: (self.effect.iter().enumerate())
                .map(|(i, e)| EffectSpec::read(e, &KeyPath::root().key("effect").index(i)))
                .collect::<Checked<_>>()?,
            event: (self.event.iter().enumerate())
                .map(|(i, e)| EventSpec::read(e, &KeyPath::root().key("event").index(i)))
                .collect::<Checked<_>>()?,
            solver: self.solver,
            output: self.output,
            compare: self.compare,
        })
    }
}

fn body(doc: BodyFile) -> Checked<BodySpec> {
    let key = || KeyPath::root().key("body");
    doc.exclusive(&key())?;
    let distribution = match (doc.shape, doc.inertia) {
        (None, None) => {
            return invalid(
                key(),
                "the body needs `shape` (e.g. { type = \"thin_disk\", radius = 0.3 }) or `inertia` ([I1, I2, I3] or a 3x3 tensor)",
            );
        }
        (Some(s), _) => Distribution::Shape(shape(&s)?),
        (None, Some(inertia)) => Distribution::Inertia(inertia),
    };
    let point_mass = (doc.point_mass.iter().enumerate())
        .map(|(index, p)| {
            let at = key().key("point_mass").index(index).key("at");
            Ok(PointMassSpec {
                mass: p.mass,
                at: required(at, p.at, "a point mass")?,
            })
        })
        .collect::<Checked<_>>()?;
    let rotor = (doc.rotor.iter().enumerate())
        .map(|(index, r)| RotorSpec::read(r, &key().key("rotor").index(index)))
        .collect::<Checked<_>>()?;
    Ok(BodySpec {
        mass: doc.mass,
        distribution,
        point_mass,
        rotor,
    })
}

/// `body.shape`: its `type` and the keys that type takes.
fn shape(doc: &ShapeFile) -> Checked<ShapeSpec> {
    let table = KeyPath::root().key("body").key("shape");
    let (kind, kind_text) = doc.kind_given(&table)?;
    let need = |name: &str, v: Option<f64>| required(table.clone().key(name), v, &kind_text);
    Ok(match kind {
        ShapeKind::ThinDisk => ShapeSpec::thin_disk(need("radius", doc.radius)?),
        ShapeKind::Disk => ShapeSpec::disk(
            need("radius", doc.radius)?,
            need("thickness", doc.thickness)?,
        ),
        ShapeKind::ThinRod => ShapeSpec::thin_rod(need("length", doc.length)?),
        ShapeKind::Sphere => ShapeSpec::sphere(need("radius", doc.radius)?),
        ShapeKind::Box => {
            ShapeSpec::cuboid(required(table.clone().key("size"), doc.size, &kind_text)?)
        }
        ShapeKind::Cylinder => {
            ShapeSpec::cylinder(need("radius", doc.radius)?, need("height", doc.height)?)
        }
    })
}

/// `[initial]`: `attitude` or `attitude_euler_deg`.
fn initial(doc: InitialFile) -> Checked<InitialSpec> {
    doc.exclusive(&KeyPath::root().key("initial"))?;
    Ok(InitialSpec {
        omega: doc.omega,
        attitude: doc.either(),
    })
}

impl From<&SceneSpec> for SceneFile {
    /// The scene written key for key: every value the typed scene holds (defaults it filled in included); an
    /// absent `t_off` (+∞) and `None`s are left out.
    fn from(spec: &SceneSpec) -> Self {
        SceneFile {
            name: spec.name.clone(),
            description: spec.description.clone(),
            body: body_file(&spec.body),
            motion: spec.motion.as_ref().map(Part::write),
            initial: spec.initial.map(|i| {
                let mut file = InitialFile {
                    omega: i.omega,
                    ..InitialFile::default()
                };
                file.set_either(i.attitude);
                file
            }),
            effect: spec.effect.iter().map(Part::write).collect(),
            event: spec.event.iter().map(Part::write).collect(),
            solver: spec.solver,
            output: spec.output,
            compare: spec.compare,
        }
    }
}

fn body_file(body: &BodySpec) -> BodyFile {
    let (shape, inertia) = match body.distribution {
        Distribution::Shape(shape) => (Some(shape_file(&shape)), None),
        Distribution::Inertia(inertia) => (None, Some(inertia)),
    };
    BodyFile {
        mass: body.mass,
        shape,
        inertia,
        point_mass: (body.point_mass.iter())
            .map(|p| PointMassFile {
                mass: p.mass,
                at: Some(p.at),
            })
            .collect(),
        rotor: body.rotor.iter().map(Part::write).collect(),
    }
}

fn shape_file(shape: &ShapeSpec) -> ShapeFile {
    let of = |kind| ShapeFile {
        kind: Some(kind),
        ..ShapeFile::default()
    };
    match *shape {
        ShapeSpec::ThinDisk { radius } => ShapeFile {
            radius: Some(radius),
            ..of(ShapeKind::ThinDisk)
        },
        ShapeSpec::Disk { radius, thickness } => ShapeFile {
            radius: Some(radius),
            thickness: Some(thickness),
            ..of(ShapeKind::Disk)
        },
        ShapeSpec::ThinRod { length } => ShapeFile {
            length: Some(length),
            ..of(ShapeKind::ThinRod)
        },
        ShapeSpec::Sphere { radius } => ShapeFile {
            radius: Some(radius),
            ..of(ShapeKind::Sphere)
        },
        ShapeSpec::Box { size } => ShapeFile {
            size: Some(size),
            ..of(ShapeKind::Box)
        },
        ShapeSpec::Cylinder { radius, height } => ShapeFile {
            radius: Some(radius),
            height: Some(height),
            ..of(ShapeKind::Cylinder)
        },
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;
    use crate::frames::Axes;
    use crate::profile::Profile;
    use crate::scene::{
        AttitudeSpec, CarrierSpec, FixedAxisSpec, HingeSpec, InertiaSpec, RateSpec, RotorDrive,
        TorqueSpec, TorqueTableSpec, parse_spec,
    };

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
            wheel.with_drive(RotorDrive::Torque {
                value: 0.1,
                profile: Profile::Sine {
                    freq_hz: 1.0,
                    phase_deg: 10.0,
                },
            }),
        ];
        for (i, shape) in shapes.into_iter().enumerate() {
            let body = BodySpec::shape(1.0, shape)
                .with_point_mass(0.1, [0.1, 0.0, 0.0])
                .with_rotor(rotors[i % rotors.len()].clone());
            let mut spec = SceneSpec::new(body, 1.0, 0.1)
                .with_effect(effects[i % effects.len()].clone())
                .with_effect(effects[(i + 3) % effects.len()].clone());
            spec.motion = Some(motions[i % motions.len()]);
            spec.initial = Some(InitialSpec {
                omega: Some([0.1, 0.2, 0.3]),
                attitude: Some(AttitudeSpec::EulerDeg([10.0, 20.0, 30.0])),
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
}
