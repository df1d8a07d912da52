//! A carrier's keys, declared once (`carrier = { … }` in `[motion]`): the file form and the reference's table
//! ([`CarrierFile`]); [`CarrierSpec`] is a [`Part`] (read from it and written back) that [`Attach`]es to a fixed
//! axis or hinge. `[motion]` registers it with one field, `#[key(part = CarrierSpec)] carrier`.

use super::Carrier;
use super::spec::{CarrierSpec, VehicleSpec};
use super::vehicle::Vehicle;
use crate::keys::{Attach, Checked, KeyPath, Keys, Part, Table, invalid, vector};
use crate::motion::fixed_axis::FixedAxis;
use crate::profile::{Profile, ProfileKeys, ProfileKind};

/// `carrier = { … }` in `[motion]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(
    header = "[motion.carrier]",
    about = "a carrier turning the axis, its point and bearings at Ω_c = rate·p(t), space axes, about the axis point"
)]
pub(crate) struct CarrierFile {
    /// space axes
    #[key(unit = "rad/s", shown = "required")]
    pub(super) rate: Option<[f64; 3]>,
    /// p = 1, or sin(2π freq_hz t + phase_deg)
    #[key(kind = "\"constant\" | \"sine\"", shown = "\"constant\"")]
    pub(super) profile: Option<ProfileKind>,
    /// ≥ 0
    #[key(unit = "Hz", shown = "required for `sine`")]
    pub(super) freq_hz: Option<f64>,
    /// `sine` only
    #[key(unit = "deg", shown = "0")]
    pub(super) phase_deg: Option<f64>,
    /// The vehicle's keys: the point the carrier turns about and its acceleration.
    #[key(flatten)]
    pub(super) vehicle: VehicleKeys,
}

/// A carrier's vehicle keys, which only an axis point can take.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct VehicleKeys {
    /// the point the carrier turns about: the axis point then moves on a circle about it
    #[key(
        unit = "m",
        shown = "the axis point",
        origin = "from the axis point, space axes at t = 0; a point of the vehicle, turning with it"
    )]
    center: Option<[f64; 3]>,
    /// the vehicle's own linear acceleration, space axes (29.43 upward = a 3 g load factor)
    #[key(unit = "m/s²", shown = "[0, 0, 0]")]
    accel: Option<[f64; 3]>,
    /// `accel` times 1, or times sin(2π freq_hz t + phase_deg) with the carrier's freq_hz and phase_deg
    #[key(kind = "\"constant\" | \"sine\"", shown = "\"constant\"")]
    accel_profile: Option<ProfileKind>,
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

    /// The vehicle's keys (`center`, `accel`, `accel_profile`) name the vehicle's point of the axis: a free body
    /// has none.
    fn refuse_unattached(file: &CarrierFile, at: &KeyPath) -> Checked<()> {
        match file.vehicle.given().first() {
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
        Ok(axis.with_support(validate(self, at)?))
    }
}

/// `carrier = { rate, profile, freq_hz, phase_deg, center, accel, accel_profile }`: `rate` required, each
/// profile `"constant"` or `"sine"`, `freq_hz` when one is a sine and only then (both share it); `accel_profile`
/// with `accel` only.
fn read(doc: &CarrierFile, at: &KeyPath) -> Checked<CarrierSpec> {
    let key = |name: &str| at.clone().key(name);
    let Some(rate) = doc.rate else {
        return invalid(
            key("rate"),
            "a carrier needs `rate = [x, y, z]`: its angular velocity (rad/s, space axes)",
        );
    };
    if doc.vehicle.accel_profile.is_some() && doc.vehicle.accel.is_none() {
        return invalid(
            key("accel_profile"),
            "`accel_profile` applies to a carrier with `accel = [x, y, z]` only",
        );
    }
    let kinds = [
        ("profile", doc.profile),
        ("accel_profile", doc.vehicle.accel_profile),
    ];
    if let Some((name, _)) = kinds.iter().find(|(_, k)| *k == Some(ProfileKind::Step)) {
        return invalid(
            key(name),
            format!("a carrier's `{name}` is \"constant\" or \"sine\", not \"step\""),
        );
    }
    let sine = kinds.iter().any(|(_, k)| *k == Some(ProfileKind::Sine));
    let shared = Profile::read(
        at,
        &ProfileKeys {
            profile: Some(if sine {
                ProfileKind::Sine
            } else {
                ProfileKind::Constant
            }),
            freq_hz: doc.freq_hz,
            phase_deg: doc.phase_deg,
            ..ProfileKeys::default()
        },
        "a sine carrier",
    )?;
    let profile_of = |kind: Option<ProfileKind>| match kind {
        Some(ProfileKind::Sine) => shared,
        _ => Profile::Constant,
    };
    let vehicle =
        (doc.vehicle.center.is_some() || doc.vehicle.accel.is_some()).then(|| VehicleSpec {
            center: doc.vehicle.center.unwrap_or([0.0; 3]),
            accel: doc.vehicle.accel.unwrap_or([0.0; 3]),
            accel_profile: profile_of(doc.vehicle.accel_profile),
        });
    Ok(CarrierSpec {
        rate,
        profile: profile_of(doc.profile),
        vehicle,
    })
}

/// The file form of a carrier; a sine's `freq_hz` and `phase_deg` are the carrier's or, with a constant rate
/// profile, the vehicle's `accel_profile`'s (validation refuses two different sines).
fn write(carrier: &CarrierSpec) -> CarrierFile {
    let rate = carrier.profile.keys();
    let accel = carrier.vehicle.map(|v| v.accel_profile.keys());
    let sine = [Some(rate), accel]
        .into_iter()
        .flatten()
        .find(|k| k.freq_hz.is_some());
    CarrierFile {
        rate: Some(carrier.rate),
        profile: rate.profile,
        freq_hz: sine.and_then(|k| k.freq_hz),
        phase_deg: sine.and_then(|k| k.phase_deg),
        vehicle: VehicleKeys {
            center: carrier.vehicle.map(|v| v.center),
            accel: carrier.vehicle.map(|v| v.accel),
            accel_profile: accel.and_then(|k| k.profile),
        },
    }
}

/// `carrier`: a finite rate (rad/s, space axes), its profiles checked ([`Profile::checked`]); a vehicle's
/// finite `center` (m) and `accel` (m/s²), and its sine the carrier's when both profiles are sines.
fn validate(carrier: &CarrierSpec, at: &KeyPath) -> Checked<Carrier> {
    let key = |name: &str| at.clone().key(name);
    let rate_s = vector(key("rate"), carrier.rate, "rad/s")?;
    let validated = Carrier::new(rate_s, carrier.profile.checked(at)?);
    let Some(vehicle) = &carrier.vehicle else {
        return Ok(validated);
    };
    let both_sines = matches!(
        (carrier.profile, vehicle.accel_profile),
        (Profile::Sine { .. }, Profile::Sine { .. })
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
        vehicle.accel_profile.checked(at)?,
    )))
}
