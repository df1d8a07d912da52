//! Hints for the likeliest export slips, read from the first row: it should be the reference's own state at that
//! time (the scene's q₀ and ω₀ at t = 0). When it is not, each slip is undone in turn and named if that makes the
//! row agree:
//!
//! - the quaternion's component order: (x, y, z, w) read as (w, x, y, z), or the other way (`--quaternion` for the
//!   generic columns `q_0..q_3`; the header for `q_w..q_z`, which name their components);
//! - its direction: q (or R) space → body where eulerdyn reads body → space (the conjugate agrees);
//! - ω's axes: space axes read as body axes (ω_b = q⁻¹ ω_read agrees), or the other way (`--omega`).
//!
//! Agreement is within [`AGREE`] (rad for the attitude, relative for ω): far above the round-off of an export with
//! 6 or more digits, far below the difference a slip makes at a generic attitude.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::QuaternionOrder;
use super::reader::{AttitudeColumns, TheirRow};
use crate::frames::Axes;
use crate::sample::Sample;

/// The first row agrees with the reference within this (rad; relative for ω).
pub const AGREE: f64 = 1e-4;

/// The hints for their first row `first` against the reference's `reference` at the same time, the attitude read
/// from `columns` and ω in `omega_axes`.
pub fn hints(
    first: &TheirRow,
    reference: &Sample,
    columns: AttitudeColumns,
    omega_axes: Axes,
) -> Vec<String> {
    let mut out = Vec::new();
    let q_ref = reference.q;
    let off = first.q.angle_to(&q_ref);
    if off > AGREE {
        let reordered = reordering(&first.q, columns);
        let (what, inverse) = match columns {
            AttitudeColumns::Matrix => ("matrices", "transposes"),
            _ => ("quaternions", "conjugates"),
        };
        out.push(
            if let Some((_, fix)) = reordered.filter(|(q, _)| q.angle_to(&q_ref) <= AGREE) {
                format!("the first row's attitude is the scene's q0 with its components in the other order: {fix}")
            } else if first.q.inverse().angle_to(&q_ref) <= AGREE {
                format!(
                    "the first row's attitude is the inverse of the scene's q0: the file's {what} turn space into \
                     body axes; export their {inverse} (eulerdyn reads body → space)"
                )
            } else {
                format!(
                    "the first row's attitude is {off:.3e} rad from the scene's q0 at t = {}: check the scene, the \
                     quaternion's order (--quaternion) and its direction (body → space)",
                    first.t
                )
            },
        );
    }
    if let Some(omega_b) = first.omega_b {
        out.extend(omega_hint(
            &omega_b,
            &first.q,
            &reference.omega_b,
            omega_axes,
        ));
    }
    out
}

/// The attitude `q` (as read from `columns`) with its components in the other order, and what to do about it;
/// `None` for a rotation matrix.
fn reordering(
    q: &UnitQuaternion<f64>,
    columns: AttitudeColumns,
) -> Option<(UnitQuaternion<f64>, &'static str)> {
    let c = q.quaternion();
    // (x, y, z, w) read as (w, x, y, z): the true w is the read z, and so on.
    let scalar_last = Quaternion::new(c.k, c.w, c.i, c.j);
    let (reordered, fix) = match columns {
        AttitudeColumns::Generic(QuaternionOrder::Wxyz) => (scalar_last, "give --quaternion xyzw"),
        AttitudeColumns::Generic(QuaternionOrder::Xyzw) => (
            Quaternion::new(c.i, c.j, c.k, c.w),
            "give --quaternion wxyz",
        ),
        AttitudeColumns::Named => (
            scalar_last,
            "the columns q_w, q_x, q_y, q_z hold x, y, z, w; name them for what they hold (or q_0..q_3 with \
             --quaternion xyzw)",
        ),
        AttitudeColumns::Matrix => return None,
    };
    Some((UnitQuaternion::from_quaternion(reordered), fix))
}

/// The hint on ω: their `omega_b` (as read) against the reference's `omega_ref_b`, with their attitude `q`.
fn omega_hint(
    omega_b: &Vector3<f64>,
    q: &UnitQuaternion<f64>,
    omega_ref_b: &Vector3<f64>,
    omega_axes: Axes,
) -> Option<String> {
    let scale = omega_ref_b.norm().max(f64::MIN_POSITIVE);
    let off = |w: &Vector3<f64>| (w - omega_ref_b).norm() / scale;
    if off(omega_b) <= AGREE {
        return None;
    }
    // Read as body axes, the numbers were ω_s: ω_b = q⁻¹ ω_s. Read as space axes, they were ω_b = q ω_read_b.
    let (other, flag) = match omega_axes {
        Axes::Body => (q.inverse_transform_vector(omega_b), "--omega space"),
        Axes::Space => (q.transform_vector(omega_b), "--omega body"),
    };
    Some(if off(&other) <= AGREE {
        format!("the first row's omega is the scene's omega0 in the other axes: give {flag}")
    } else {
        format!(
            "the first row's omega differs from the scene's omega0 by {:.3e} (relative): check the scene, omega's \
             axes (--omega) and its unit (rad/s)",
            off(omega_b)
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::Vector;

    fn reference(q: UnitQuaternion<f64>, omega_b: Vector3<f64>) -> Sample {
        let zero = (Vector::zeros(), Vector::zeros());
        Sample::rigid(0.0, q, Vector::new(omega_b), zero, zero)
    }

    #[test]
    fn each_slip_is_named_and_a_right_row_gets_none() {
        let q0 = UnitQuaternion::from_euler_angles(0.3, -0.5, 1.1);
        let w0 = Vector3::new(0.4, 0.2, 2.0);
        let r = reference(q0, w0);
        let row = |q, w| TheirRow {
            t: 0.0,
            q,
            omega_b: Some(w),
        };
        let right = row(q0, w0);
        assert!(
            hints(
                &right,
                &r,
                AttitudeColumns::Generic(QuaternionOrder::Wxyz),
                Axes::Body
            )
            .is_empty()
        );
        // xyzw in the file read as wxyz: the read q is (x, y, z, w) of q0.
        let c = q0.quaternion();
        let swapped = UnitQuaternion::from_quaternion(Quaternion::new(c.i, c.j, c.k, c.w));
        let h = hints(
            &row(swapped, w0),
            &r,
            AttitudeColumns::Generic(QuaternionOrder::Wxyz),
            Axes::Body,
        );
        assert_eq!(h.len(), 1);
        assert!(h[0].contains("give --quaternion xyzw"), "{h:?}");
        let h = hints(
            &row(q0.inverse(), w0),
            &r,
            AttitudeColumns::Generic(QuaternionOrder::Wxyz),
            Axes::Body,
        );
        assert!(h[0].contains("conjugates"), "{h:?}");
        // ω in space axes read as body axes.
        let h = hints(
            &row(q0, q0 * w0),
            &r,
            AttitudeColumns::Generic(QuaternionOrder::Wxyz),
            Axes::Body,
        );
        assert_eq!(
            h,
            ["the first row's omega is the scene's omega0 in the other axes: give --omega space"]
        );
        // Read as space axes (ω_b = q⁻¹ ω), numbers that were body axes.
        let h = hints(
            &row(q0, q0.inverse() * w0),
            &r,
            AttitudeColumns::Generic(QuaternionOrder::Wxyz),
            Axes::Space,
        );
        assert!(h[0].contains("give --omega body"), "{h:?}");
        let h = hints(
            &row(q0, w0 * 2.0),
            &r,
            AttitudeColumns::Generic(QuaternionOrder::Wxyz),
            Axes::Body,
        );
        assert!(
            h[0].contains("differs from the scene's omega0 by 1.000e0"),
            "{h:?}"
        );
    }
}
