//! Butcher tableaus of the own Runge–Kutta methods as constant data, run by [`super::explicit_rk::step`].
//!
//! An explicit s-stage method (HNW I §II.1, eq. (1.8)): k_i = f(t + c_i h, y + h Σ_{j<i} a_ij k_j),
//! y₁ = y + h Σ_j b_j k_j. The embedded pairs add error weights e_j (the local error estimate is h Σ_j e_j k_j).

#![allow(clippy::excessive_precision)]

/// How the step applies the weights b to the stages; both forms are y₁ = y + h Σ_j b_j k_j in exact arithmetic and
/// differ in rounding only (each is the form of the code the tableau comes from).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Increment {
    /// y₁ = y + Σ_j (b_j h) k_j: h folded into the weights (`dopri5.f`).
    FoldedStep,
    /// y₁ = y + (Σ_j b_j k_j)·(h/d), the slope summed first with the weights stored as numerators b_j·d
    /// (`dop853.f`, d = 1; the classical RK4 formula (k1 + 2(k2 + k3) + k4)·h/6, d = 6).
    Slope {
        /// The common denominator d of the weights.
        denominator: f64,
    },
}

/// An explicit Runge–Kutta method with `S` stages (a strictly lower triangular).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ButcherTableau<const S: usize> {
    /// Nodes c_i; a node c_i = 1 is evaluated at the end time of the step, t + h as the driver computes it.
    pub c: [f64; S],
    /// Coefficients a_ij, j < i.
    pub a: [[f64; S]; S],
    /// Weights of the solution (numerators over the denominator of [`Increment::Slope`]).
    pub b: [f64; S],
    /// How the weights are applied.
    pub increment: Increment,
    /// First same as last: the last stage is f(t + h, y₁) (its row of a is b), so it is not computed from a but
    /// from y₁, and it is the next step's k1.
    pub fsal: bool,
}

impl<const S: usize> ButcherTableau<S> {
    /// Time of stage i: t + c_i·h, or `t_end` when c_i = 1 (so the last step of a row interval lands exactly on it).
    #[inline(always)]
    pub fn node(&self, i: usize, t: f64, t_end: f64, h: f64) -> f64 {
        if self.c[i] == 1.0 {
            t_end
        } else {
            t + self.c[i] * h
        }
    }
}

/// The classical Runge–Kutta method of order 4 (HNW I §II.1, Table 1.2, left): c = (0, ½, ½, 1), the only
/// non-zero a_ij are a21 = a32 = ½, a43 = 1; b = (1, 2, 2, 1)/6.
pub(crate) const RK4: ButcherTableau<4> = ButcherTableau {
    c: [0.0, 0.5, 0.5, 1.0],
    a: [
        [0.0; 4],
        [0.5, 0.0, 0.0, 0.0],
        [0.0, 0.5, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ],
    b: [1.0, 2.0, 2.0, 1.0],
    increment: Increment::Slope { denominator: 6.0 },
    fsal: false,
};

/// Dormand–Prince 5(4), DOPRI5 (Dormand & Prince 1980; HNW I §II.5, Table 5.2; Hairer's `dopri5.f`). Seven
/// stages, the seventh f(t + h, y₁) (a7j = b_j): FSAL, 6 evaluations per step.
pub(crate) const DOPRI5: ButcherTableau<7> = ButcherTableau {
    c: [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    a: [
        [0.0; 7],
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0, 0.0],
        [
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
            0.0,
            0.0,
        ],
        DOPRI5_B,
    ],
    b: DOPRI5_B,
    increment: Increment::FoldedStep,
    fsal: true,
};

/// The 5th-order weights of DOPRI5 (b2 = b7 = 0).
const DOPRI5_B: [f64; 7] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
    0.0,
];

/// Error weights e = b − b̂ of DOPRI5 (E1..E7 of `dopri5.f`; HNW I §II.5, Table 5.2).
pub(crate) const DOPRI5_ERROR: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Dormand–Prince 8(5,3), DOP853 (Prince & Dormand 1981; HNW I §II.5), coefficients copied from Hairer's
/// `dop853.f` (C2..C11, A21..A1211, B1..B12). Twelve stages, the twelfth at c12 = 1, t + h (`XPH` in `dop853.f`;
/// ode_solvers 0.6.2 wrongly tabulates 0). Not FSAL in the tableau: the driver evaluates f(t + h, y₁) after
/// acceptance.
pub(crate) const DOP853: ButcherTableau<12> = ButcherTableau {
    c: [
        0.0,
        0.526001519587677318785587544488E-01,
        0.789002279381515978178381316732E-01,
        0.118350341907227396726757197510E+00,
        0.281649658092772603273242802490E+00,
        0.333333333333333333333333333333E+00,
        0.25E+00,
        0.307692307692307692307692307692E+00,
        0.651282051282051282051282051282E+00,
        0.6E+00,
        0.857142857142857142857142857142E+00,
        1.0,
    ],
    a: DOP853_A,
    b: [
        5.42937341165687622380535766363E-2,
        0.0,
        0.0,
        0.0,
        0.0,
        4.45031289275240888144113950566E0,
        1.89151789931450038304281599044E0,
        -5.8012039600105847814672114227E0,
        3.1116436695781989440891606237E-1,
        -1.52160949662516078556178806805E-1,
        2.01365400804030348374776537501E-1,
        4.47106157277725905176885569043E-2,
    ],
    increment: Increment::Slope { denominator: 1.0 },
    fsal: false,
};

/// A of DOP853 (`dop853.f`; the zero columns 2 and 3 of rows 4..12 are zeros there too).
#[rustfmt::skip]
const DOP853_A: [[f64; 12]; 12] = [
    [0.0; 12],
    [5.26001519587677318785587544488E-2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1.97250569845378994544595329183E-2, 5.91751709536136983633785987549E-2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
     0.0, 0.0],
    [2.95875854768068491816892993775E-2, 0.0, 8.87627564304205475450678981324E-2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
     0.0, 0.0],
    [2.41365134159266685502369798665E-1, 0.0, -8.84549479328286085344864962717E-1,
     9.24834003261792003115737966543E-1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.7037037037037037037037037037E-2, 0.0, 0.0, 1.70828608729473871279604482173E-1,
     1.25467687566822425016691814123E-1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.7109375E-2, 0.0, 0.0, 1.70252211019544039314978060272E-1, 6.02165389804559606850219397283E-2, -1.7578125E-2,
     0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.70920001185047927108779319836E-2, 0.0, 0.0, 1.70383925712239993810214054705E-1,
     1.07262030446373284651809199168E-1, -1.53194377486244017527936158236E-2, 8.27378916381402288758473766002E-3,
     0.0, 0.0, 0.0, 0.0, 0.0],
    [6.24110958716075717114429577812E-1, 0.0, 0.0, -3.36089262944694129406857109825E0,
     -8.68219346841726006818189891453E-1, 2.75920996994467083049415600797E1, 2.01540675504778934086186788979E1,
     -4.34898841810699588477366255144E1, 0.0, 0.0, 0.0, 0.0],
    [4.77662536438264365890433908527E-1, 0.0, 0.0, -2.48811461997166764192642586468E0,
     -5.90290826836842996371446475743E-1, 2.12300514481811942347288949897E1, 1.52792336328824235832596922938E1,
     -3.32882109689848629194453265587E1, -2.03312017085086261358222928593E-2, 0.0, 0.0, 0.0],
    [-9.3714243008598732571704021658E-1, 0.0, 0.0, 5.18637242884406370830023853209E0,
     1.09143734899672957818500254654E0, -8.14978701074692612513997267357E0, -1.85200656599969598641566180701E1,
     2.27394870993505042818970056734E1, 2.49360555267965238987089396762E0, -3.0467644718982195003823669022E0, 0.0,
     0.0],
    [2.27331014751653820792359768449E0, 0.0, 0.0, -1.05344954667372501984066689879E1,
     -2.00087205822486249909675718444E0, -1.79589318631187989172765950534E1, 2.79488845294199600508499808837E1,
     -2.85899827713502369474065508674E0, -8.87285693353062954433549289258E0, 1.23605671757943030647266201528E1,
     6.43392746015763530355970484046E-1, 0.0],
];

/// Weights ER1..ER12 of DOP853's 5th-order error estimate (`dop853.f`; ER2..ER5 are 0).
pub(crate) const DOP853_ERROR5: [f64; 12] = [
    0.1312004499419488073250102996E-01,
    0.0,
    0.0,
    0.0,
    0.0,
    -0.1225156446376204440720569753E+01,
    -0.4957589496572501915214079952E+00,
    0.1664377182454986536961530415E+01,
    -0.3503288487499736816886487290E+00,
    0.3341791187130174790297318841E+00,
    0.8192320648511571246570742613E-01,
    -0.2235530786388629525884427845E-01,
];

/// Weights BHH1, BHH2, BHH3 of DOP853's 3rd-order solution, on k1, k9 and k12 (`dop853.f`): the 3rd-order error
/// estimate is Σ_j b_j k_j − Σ_j bhh_j k_j.
pub(crate) const DOP853_ERROR3: [f64; 12] = [
    0.244094488188976377952755905512E+00,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    0.733846688281611857341361741547E+00,
    0.0,
    0.0,
    0.220588235294117647058823529412E-01,
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The weights b_j themselves (numerators over the denominator).
    fn weights<const S: usize>(tab: &ButcherTableau<S>) -> [f64; S] {
        let d = match tab.increment {
            Increment::FoldedStep => 1.0,
            Increment::Slope { denominator } => denominator,
        };
        tab.b.map(|b| b / d)
    }

    /// Largest |Σ_j a_ij − c_i| over the stages.
    fn row_sum_defect<const S: usize>(tab: &ButcherTableau<S>) -> f64 {
        (0..S)
            .map(|i| (tab.a[i].iter().sum::<f64>() - tab.c[i]).abs())
            .fold(0.0, f64::max)
    }

    /// Σ_i b_i c_i^(q−1) − 1/q, the bushy-tree order condition of order q.
    fn quadrature_defect<const S: usize>(b: &[f64; S], c: &[f64; S], q: i32) -> f64 {
        let s: f64 = (0..S).map(|i| b[i] * c[i].powi(q - 1)).sum();
        s - 1.0 / f64::from(q)
    }

    #[test]
    fn rk4_is_of_order_4() {
        assert!(row_sum_defect(&RK4) == 0.0);
        let b = weights(&RK4);
        for q in 1..=4 {
            assert!(quadrature_defect(&b, &RK4.c, q).abs() < 1e-15, "q = {q}");
        }
        assert!(quadrature_defect(&b, &RK4.c, 5).abs() > 1e-3);
    }

    #[test]
    fn dopri5_row_sums_are_nodes() {
        for i in 1..7 {
            let s: f64 = DOPRI5.a[i].iter().sum();
            assert!(
                (s - DOPRI5.c[i]).abs() < 1e-15,
                "row {i}: {s} vs {}",
                DOPRI5.c[i]
            );
        }
        // FSAL: the last row is b.
        assert_eq!(DOPRI5.a[6], DOPRI5.b);
    }

    #[test]
    fn dopri5_quadrature_conditions_order_5() {
        // Σ b_i c_i^(q−1) = 1/q for q = 1..5 (bushy-tree order conditions).
        for q in 1..=5 {
            let s = quadrature_defect(&DOPRI5.b, &DOPRI5.c, q);
            assert!(s.abs() < 1e-15, "q = {q}: {s}");
        }
        // The embedded 4th-order weights b̂ = b − e satisfy them to q = 4 but not 5.
        let b_hat: [f64; 7] = std::array::from_fn(|i| DOPRI5.b[i] - DOPRI5_ERROR[i]);
        for q in 1..=4 {
            let s = quadrature_defect(&b_hat, &DOPRI5.c, q);
            assert!(s.abs() < 1e-15, "q = {q}: {s}");
        }
        assert!(DOPRI5_ERROR.iter().sum::<f64>().abs() < 1e-17);
    }

    #[test]
    fn dop853_row_sums_are_nodes_and_c12_is_one() {
        // c_i = Σ_j a_ij; in particular the last row sums to 1, so stage 12 sits at t + h.
        for i in 0..12 {
            let s: f64 = DOP853.a[i].iter().sum();
            let c = DOP853.c[i];
            assert!((s - c).abs() < 1e-13, "stage {}: Σa = {s}, c = {c}", i + 1);
        }
        let last: f64 = DOP853.a[11].iter().sum();
        assert!((last - 1.0).abs() < 1e-13);
        assert_eq!(DOP853.c[11], 1.0);
    }

    #[test]
    fn dop853_quadrature_conditions_order_8() {
        for q in 1..=8 {
            let s = quadrature_defect(&DOP853.b, &DOP853.c, q);
            assert!(s.abs() < 1e-13, "q = {q}: {s}");
        }
    }

    #[test]
    fn dop853_stage_order_condition() {
        // Σ_i b_i Σ_j a_ij c_j = 1/6 (the tree [[τ]]) — catches a misplaced A entry.
        let s: f64 = (0..12)
            .map(|i| {
                let inner: f64 = (0..12).map(|j| DOP853.a[i][j] * DOP853.c[j]).sum();
                DOP853.b[i] * inner
            })
            .sum();
        assert!((s - 1.0 / 6.0).abs() < 1e-13, "{s}");
    }

    #[test]
    fn dop853_error_weights_annihilate_constants() {
        assert!(DOP853_ERROR5.iter().sum::<f64>().abs() < 1e-13);
        assert!((DOP853_ERROR3.iter().sum::<f64>() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn tableaus_are_explicit() {
        fn strictly_lower<const S: usize>(tab: &ButcherTableau<S>) -> bool {
            (0..S).all(|i| (i..S).all(|j| tab.a[i][j] == 0.0))
        }
        assert!(strictly_lower(&RK4) && strictly_lower(&DOPRI5) && strictly_lower(&DOP853));
    }
}
