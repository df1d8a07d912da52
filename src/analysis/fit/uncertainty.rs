//! What the optimum's Jacobian says about the estimates: the covariance C = (JᵀJ)⁻¹ of the weighted problem
//! (Seber & Wild, *Nonlinear Regression*, §2.1–2.2), standard errors and 95 % intervals, the correlation matrix,
//! and a parameter the data cannot determine (a column of J that is, to round-off, zero or a combination of the
//! others, each column taken at its parameter's size).

use nalgebra::{DMatrix, DVector, Dyn};

/// The two-sided 95 % quantile of the normal distribution.
pub const Z95: f64 = 1.959_963_984_540_054;

/// A direction whose singular value is below this fraction of the largest (columns scaled by their parameters'
/// sizes) is not determined by the data: ~1e8 times round-off's relative size in the sensitivities.
pub const UNDETERMINED: f64 = 1e-8;

/// The SVD of J with each column multiplied by its parameter's typical size (`scales`): the change of the
/// residuals when a parameter moves by its own size. `Err(k)`: column k is not finite.
fn scaled_svd(
    jacobian: &DMatrix<f64>,
    scales: &DVector<f64>,
) -> Result<nalgebra::SVD<f64, Dyn, Dyn>, usize> {
    if let Some(k) = (jacobian.column_iter()).position(|c| c.iter().any(|v| !v.is_finite())) {
        return Err(k);
    }
    let scaled = DMatrix::from_fn(jacobian.nrows(), jacobian.ncols(), |r, c| {
        jacobian[(r, c)] * scales[c]
    });
    Ok(scaled.svd(false, true))
}

/// The smallest singular value of J with its columns scaled by `scales` over the largest (0 when a column is not
/// finite): how well the data determine every parameter at once.
pub fn conditioning(jacobian: &DMatrix<f64>, scales: &DVector<f64>) -> f64 {
    match scaled_svd(jacobian, scales) {
        Err(_) => 0.0,
        Ok(svd) if svd.singular_values.max() > 0.0 => {
            svd.singular_values.min() / svd.singular_values.max()
        }
        Ok(_) => 0.0,
    }
}

/// The coordinate the data cannot determine, if any: the largest entry of the right singular vector of the
/// smallest singular value of J with its columns scaled by `scales`, when that value is below [`UNDETERMINED`] of
/// the largest (a column that is, to round-off, zero or a combination of the others).
pub fn undetermined(jacobian: &DMatrix<f64>, scales: &DVector<f64>) -> Option<usize> {
    let svd = match scaled_svd(jacobian, scales) {
        Err(k) => return Some(k),
        Ok(svd) => svd,
    };
    let v_t = svd.v_t.expect("asked for V");
    let (k_min, s_min) = (svd.singular_values.iter().enumerate())
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map(|(k, s)| (k, *s))?;
    let s_max = svd.singular_values.max();
    if s_min > UNDETERMINED * s_max {
        return None;
    }
    (v_t.row(k_min).iter().enumerate())
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .map(|(k, _)| k)
}

/// C = (JᵀJ)⁻¹ of the weighted residuals (J of full column rank: [`undetermined`] has said so), by the SVD of J:
/// C = V Σ⁻² Vᵀ.
pub fn covariance(jacobian: &DMatrix<f64>) -> DMatrix<f64> {
    let svd = jacobian.clone().svd(false, true);
    let v_t = svd.v_t.expect("asked for V");
    let inv_sq = DVector::from_iterator(
        svd.singular_values.len(),
        svd.singular_values.iter().map(|s| 1.0 / (s * s)),
    );
    v_t.transpose() * DMatrix::from_diagonal(&inv_sq) * v_t
}

/// The correlation matrix of `covariance`; a variance of 0 (a held value) correlates with nothing.
pub fn correlation(covariance: &DMatrix<f64>) -> DMatrix<f64> {
    let sd: Vec<f64> = (0..covariance.nrows())
        .map(|k| covariance[(k, k)].max(0.0).sqrt())
        .collect();
    DMatrix::from_fn(covariance.nrows(), covariance.ncols(), |r, c| {
        if r == c {
            1.0
        } else if sd[r] > 0.0 && sd[c] > 0.0 {
            covariance[(r, c)] / (sd[r] * sd[c])
        } else {
            0.0
        }
    })
}
