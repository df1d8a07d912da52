//! A carrier's keys, declared once (`carrier = { … }` in `[motion]`): the file form and the reference's table
//! ([`CarrierFile`]); [`CarrierSpec`] is a [`Part`] (read from it and written back) that [`Attach`]es to a fixed
//! axis or hinge. `[motion]` registers it with one line, `part carrier: CarrierSpec`.

use serde::{Deserialize, Serialize};

use super::spec::{CarrierProfileSpec, CarrierSpec, VehicleSpec};
use super::vehicle::Vehicle;
use super::{Carrier, CarrierProfile};
use crate::keys::{
    Attach, Checked, KeyPath, Part, Table, file_table, finite, invalid, key, required, vector,
};
use crate::motion::fixed_axis::FixedAxis;

file_table! {
    /// `carrier = { … }` in `[motion]`.
    #[derive(Copy)]
    pub(crate) struct CarrierFile(pub(super)) "[motion.carrier]",
        "a carrier turning the axis, its point and bearings at Ω_c = rate·p(t), space axes, about the axis point" {
        arr rate: [f64; 3] = key("[x, y, z]", "rad/s", "required", "", "space axes");
        opt profile: CarrierProfileKind = key("\"constant\" | \"sine\"", "–", "\"constant\"", "", "p = 1, or sin(2π freq_hz t + phase_deg)");
        @sine;
        arr center: [f64; 3] = key("[x, y, z]", "m", "the axis point", "from the axis point, space axes at t = 0; a point of the vehicle, turning with it", "the point the carrier turns about: the axis point then moves on a circle about it");
        arr accel: [f64; 3] = key("[x, y, z]", "m/s²", "[0, 0, 0]", "", "the vehicle's own linear acceleration, space axes (29.43 upward = a 3 g load factor)");
        opt accel_profile: CarrierProfileKind = key("\"constant\" | \"sine\"", "–", "\"constant\"", "", "`accel` times 1, or times sin(2π freq_hz t + phase_deg) with the carrier's freq_hz and phase_deg");
    }
}

/// A carrier's `profile`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum CarrierProfileKind {
    Constant,
    Sine,
}

impl Part for CarrierSpec {
    type File = CarrierFile;
    const TABLE: Table = CarrierFile::TABLE;

    fn read(file: &CarrierFile, at: &KeyPath) -> Checked<Self> {
        read(file, at)
    }

    fn write(&self) -> CarrierFile {
        write(self)
    }

    /// `center` and `accel` name the vehicle's point of the axis: a free body has none.
    fn refuse_unattached(file: &CarrierFile, at: &KeyPath) -> Checked<()> {
        match (file.given().into_iter()).find(|k| ["center", "accel"].contains(k)) {
            Some(name) => invalid(
                at.clone().key(name),
                format!(
                    "`{name}` applies to the carrier of a fixed-axis or hinge motion; a free body has no axis point"
                ),
            ),
            None => Ok(()),
        }
    }
}

impl Attach<FixedAxis> for CarrierSpec {
    fn attach(&self, axis: FixedAxis, at: &KeyPath) -> Checked<FixedAxis> {
        Ok(axis.with_carrier(validate(self, at)?))
    }
}

/// `carrier = { rate, profile, freq_hz, phase_deg, center, accel, accel_profile }`: `rate` required, `freq_hz`
/// when `profile` or `accel_profile` is a sine and only then; `accel_profile` with `accel` only.
fn read(doc: &CarrierFile, at: &KeyPath) -> Checked<CarrierSpec> {
    let key = |name: &str| at.clone().key(name);
    let Some(rate) = doc.rate else {
        return invalid(
            key("rate"),
            "a carrier needs `rate = [x, y, z]`: its angular velocity (rad/s, space axes)",
        );
    };
    if doc.accel_profile.is_some() && doc.accel.is_none() {
        return invalid(
            key("accel_profile"),
            "`accel_profile` applies to a carrier with `accel = [x, y, z]` only",
        );
    }
    let kinds = [doc.profile, doc.accel_profile].map(|k| k.unwrap_or(CarrierProfileKind::Constant));
    let sine = if kinds.contains(&CarrierProfileKind::Sine) {
        CarrierProfileSpec::Sine {
            freq_hz: required(key("freq_hz"), doc.freq_hz, "a sine carrier")?,
            phase_deg: doc.phase_deg.unwrap_or(0.0),
        }
    } else {
        if let Some(name) = (doc.given().into_iter()).find(|k| ["freq_hz", "phase_deg"].contains(k))
        {
            return invalid(
                key(name),
                format!("`{name}` applies to a carrier with profile = \"sine\" only"),
            );
        }
        CarrierProfileSpec::Constant
    };
    let profile_of = |kind| match kind {
        CarrierProfileKind::Constant => CarrierProfileSpec::Constant,
        CarrierProfileKind::Sine => sine,
    };
    let vehicle = (doc.center.is_some() || doc.accel.is_some()).then(|| VehicleSpec {
        center: doc.center.unwrap_or([0.0; 3]),
        accel: doc.accel.unwrap_or([0.0; 3]),
        accel_profile: profile_of(kinds[1]),
    });
    Ok(CarrierSpec {
        rate,
        profile: profile_of(kinds[0]),
        vehicle,
    })
}

/// The file form of a carrier; a sine's `freq_hz` and `phase_deg` are the carrier's or, with a constant rate
/// profile, the vehicle's `accel_profile`'s (validation refuses two different sines).
fn write(carrier: &CarrierSpec) -> CarrierFile {
    let kind_of = |profile: &CarrierProfileSpec| match profile {
        CarrierProfileSpec::Constant => (CarrierProfileKind::Constant, None),
        CarrierProfileSpec::Sine { freq_hz, phase_deg } => {
            (CarrierProfileKind::Sine, Some((*freq_hz, *phase_deg)))
        }
    };
    let (profile, rate_sine) = kind_of(&carrier.profile);
    let accel_kind = carrier.vehicle.map(|v| kind_of(&v.accel_profile));
    let sine = rate_sine.or(accel_kind.and_then(|(_, sine)| sine));
    CarrierFile {
        rate: Some(carrier.rate),
        profile: Some(profile),
        freq_hz: sine.map(|(freq_hz, _)| freq_hz),
        phase_deg: sine.map(|(_, phase_deg)| phase_deg),
        center: carrier.vehicle.map(|v| v.center),
        accel: carrier.vehicle.map(|v| v.accel),
        accel_profile: accel_kind.map(|(kind, _)| kind),
    }
}

/// `carrier`: a finite rate (rad/s, space axes); a sine's frequency finite and ≥ 0, its phase finite; a vehicle's
/// finite `center` (m) and `accel` (m/s²), and its sine the carrier's when both profiles are sines.
fn validate(carrier: &CarrierSpec, at: &KeyPath) -> Checked<Carrier> {
    let key = |name: &str| at.clone().key(name);
    let rate_s = vector(key("rate"), carrier.rate, "rad/s")?;
    let validated = Carrier::new(rate_s, carrier_profile(&carrier.profile, at)?);
    let Some(vehicle) = &carrier.vehicle else {
        return Ok(validated);
    };
    let both_sines = matches!(
        (carrier.profile, vehicle.accel_profile),
        (
            CarrierProfileSpec::Sine { .. },
            CarrierProfileSpec::Sine { .. }
        )
    );
    if both_sines && carrier.profile != vehicle.accel_profile {
        return invalid(
            key("accel_profile"),
            "a sine `accel_profile` shares the carrier's `freq_hz` and `phase_deg`: give one sine",
        );
    }
    Ok(validated.with_vehicle(Vehicle::new(
        vector(key("center"), vehicle.center, "m")?,
        vector(key("accel"), vehicle.accel, "m/s²")?,
        carrier_profile(&vehicle.accel_profile, at)?,
    )))
}

/// A carrier's (or its vehicle's) profile: a sine's frequency finite and ≥ 0, its phase finite.
fn carrier_profile(profile: &CarrierProfileSpec, at: &KeyPath) -> Checked<CarrierProfile> {
    let key = |name: &str| at.clone().key(name);
    Ok(match *profile {
        CarrierProfileSpec::Constant => CarrierProfile::Constant,
        CarrierProfileSpec::Sine { freq_hz, phase_deg } => {
            let freq_hz = finite(key("freq_hz"), freq_hz, "Hz")?;
            if freq_hz < 0.0 {
                return invalid(key("freq_hz"), format!("must be >= 0 (Hz), got {freq_hz}"));
            }
            CarrierProfile::Sine {
                omega_f: std::f64::consts::TAU * freq_hz,
                phase: finite(key("phase_deg"), phase_deg, "degrees")?.to_radians(),
            }
        }
    })
}
