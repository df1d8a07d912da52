//! The lines `eulerdyn check` prints of a body that changes shape: what moves, and the system (mass, centre of
//! mass, inertia about it) at t = 0 and once the last motion has ended.

use super::path::Side;
use super::{Distribution, MassPath, ShapeChange};
use crate::text::{Description, for_people, line, vec3};

impl ShapeChange {
    /// Appends the shape change's lines to `w`; `body_mass` is `[body]`'s mass.
    pub fn describe(&self, w: &mut Description, body_mass: f64) {
        match &self.distribution {
            Distribution::Masses { masses, .. } => {
                line(
                    w,
                    "shape change",
                    &format!(
                        "{} mass(es) moved inside the body; [body] is the rest of it; H = I(t) omega + h about \
                         the system's C(t)",
                        masses.len()
                    ),
                );
                for m in masses {
                    let path = match &m.path {
                        MassPath::Move {
                            from,
                            to,
                            start,
                            duration,
                            profile,
                        } => format!(
                            "from {} to {} m, t = {} to {} s, {}",
                            vec3(from),
                            vec3(to),
                            for_people(*start),
                            for_people(start + duration),
                            crate::named::Named::name(profile)
                        ),
                        MassPath::Table { t, .. } => {
                            format!(
                                "along its table, {} rows, t = {} to {} s",
                                t.len(),
                                t[0],
                                t[t.len() - 1]
                            )
                        }
                    };
                    line(
                        w,
                        "",
                        &format!("{}: {} kg {path}", m.name, for_people(m.mass)),
                    );
                }
            }
            Distribution::Table { history, .. } => line(
                w,
                "shape change",
                &format!(
                    "inertia from {} ({} rows, t = {} to {} s), taken to carry no moment of momentum relative \
                     to the body (h = 0)",
                    history.path.display(),
                    history.t.len(),
                    history.t[0],
                    history.t[history.t.len() - 1]
                ),
            ),
        }
        let mass = self.distribution.mass(body_mass);
        for (label, t) in [("system", 0.0), ("", self.end())] {
            let s = self.at(t, Side::After);
            let i = s.inertia_b;
            line(
                w,
                label,
                &format!(
                    "at t = {} s: mass {} kg, C {} m, I about C [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]] kg*m^2",
                    for_people(t),
                    for_people(mass),
                    vec3(&s.c_b),
                    for_people(i[(0, 0)]),
                    for_people(i[(0, 1)]),
                    for_people(i[(0, 2)]),
                    for_people(i[(1, 0)]),
                    for_people(i[(1, 1)]),
                    for_people(i[(1, 2)]),
                    for_people(i[(2, 0)]),
                    for_people(i[(2, 1)]),
                    for_people(i[(2, 2)]),
                ),
            );
        }
        line(
            w,
            "",
            "H is the invariant without external moment; the kinetic energy is not (P_internal is the internal drives' power)",
        );
    }
}
