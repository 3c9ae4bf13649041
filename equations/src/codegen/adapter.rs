//! The ODE adapter generated into a built model's module: layout constants
//! and `System`, which implements `pegdyn::system::OdeSystem` with the
//! model's exact right-hand side, exact Jacobian and time derivative.

use proc_macro2::TokenStream;
use quote::quote;

use super::tokens::{ident, ulit as lit};
use crate::model::Layout;

/// The adapter items, emitted inside `pub mod <model>`.
pub(crate) fn tokens(l: &Layout) -> TokenStream {
    let n = l.state.len();
    let np = l.params.len();
    let (nl, npl) = (lit(n), lit(np));
    let mut consts = Vec::new();
    for (k, (name, doc)) in l.state.iter().zip(&l.state_docs).enumerate() {
        let c = ident(&format!("X_{}", name.to_uppercase()));
        let d = format!(" Index of `{name}` in `x`: {doc}.");
        let k = lit(k);
        consts.push(quote! { #[doc = #d] pub const #c: usize = #k; });
    }
    let (xd, pd) = (&l.state_docs, &l.param_docs);
    consts.push(quote! {
        /// What each state component is, with units (order of `x`).
        pub const X_DOCS: [&str; #nl] = [#(#xd),*];
        /// What each parameter is, with units (order of `p`).
        pub const P_DOCS: [&str; #npl] = [#(#pd),*];
        /// Dimension of the state `x`.
        pub const STATE_DIM: usize = #nl;
        /// Number of parameters `p`.
        pub const PARAM_DIM: usize = #npl;
    });
    // Arguments after `x` (and `qdd`): `&self.p` when there are parameters,
    // then `&SVector::new(t)` when the model depends on time.
    let p_arg = (np > 0).then(|| quote!(&self.p));
    let t_arg = l.time.then(|| quote!(&nalgebra::SVector::<f64, 1>::new(t)));
    let rest: Vec<TokenStream> = p_arg.into_iter().chain(t_arg).collect();
    let nan_v = quote!(nalgebra::SVector::<f64, #nl>::repeat(f64::NAN));
    let nan_m = quote!(nalgebra::SMatrix::<f64, #nl, #nl>::repeat(f64::NAN));
    let body = match l.dof {
        Some(dof) => {
            let dl = lit(dof);
            let rhs = if l.closed_rhs {
                quote!(rhs(x, #(#rest),*))
            } else {
                quote! {
                    let qdd = self.accelerations(t, x);
                    let mut xdot = nalgebra::SVector::<f64, #nl>::zeros();
                    xdot.fixed_rows_mut::<#dl>(0).copy_from(&x.fixed_rows::<#dl>(#dl));
                    xdot.fixed_rows_mut::<#dl>(#dl).copy_from(&qdd);
                    xdot
                }
            };
            let time_derivative = if l.time {
                quote! {
                    let DynamicsOut { mass, forcing } = dynamics(x, #(#rest),*);
                    let lu = mass.lu();
                    let Some(qdd) = lu.solve(&forcing) else { return #nan_v };
                    let tt = time_terms(x, &qdd, #(#rest),*);
                    let mut d = nalgebra::SVector::<f64, #nl>::zeros();
                    match lu.solve(&tt) {
                        Some(a) => d.fixed_rows_mut::<#dl>(#dl).copy_from(&a),
                        None => return #nan_v,
                    }
                    d
                }
            } else {
                quote!(nalgebra::SVector::<f64, #nl>::zeros())
            };
            quote! {
                impl System {
                    /// The accelerations q̈ = M⁻¹ f at `(t, x)`, by an LU
                    /// solve of the mass matrix (NaN entries when M is
                    /// singular, so that the integrator reports it).
                    pub fn accelerations(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SVector<f64, #dl> {
                        let _ = t;
                        let DynamicsOut { mass, forcing } = dynamics(x, #(#rest),*);
                        mass.lu().solve(&forcing).unwrap_or_else(|| nalgebra::SVector::repeat(f64::NAN))
                    }
                }
                impl pegdyn::system::OdeSystem<#nl> for System {
                    fn rhs(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SVector<f64, #nl> {
                        let _ = t;
                        #rhs
                    }
                    /// Exact: ∂ẋ/∂x = [[0, I], [M⁻¹G]] with G from `jacobian_terms`.
                    fn jacobian(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SMatrix<f64, #nl, #nl> {
                        let _ = t;
                        let DynamicsOut { mass, forcing } = dynamics(x, #(#rest),*);
                        let lu = mass.lu();
                        let Some(qdd) = lu.solve(&forcing) else { return #nan_m };
                        let terms = jacobian_terms(x, &qdd, #(#rest),*);
                        let Some(rows) = lu.solve(&terms) else { return #nan_m };
                        let mut j = nalgebra::SMatrix::<f64, #nl, #nl>::zeros();
                        for i in 0..#dl {
                            j[(i, #dl + i)] = 1.0;
                        }
                        j.fixed_view_mut::<#dl, #nl>(#dl, 0).copy_from(&rows);
                        j
                    }
                    fn time_derivative(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SVector<f64, #nl> {
                        let _ = (t, x);
                        #time_derivative
                    }
                }
            }
        }
        None => {
            let td = if l.time {
                quote!(rhs_t(x, #(#rest),*))
            } else {
                quote!(nalgebra::SVector::<f64, #nl>::zeros())
            };
            quote! {
                impl pegdyn::system::OdeSystem<#nl> for System {
                    fn rhs(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SVector<f64, #nl> {
                        let _ = t;
                        rhs(x, #(#rest),*)
                    }
                    /// Exact: the generated `jacobian`.
                    fn jacobian(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SMatrix<f64, #nl, #nl> {
                        let _ = t;
                        jacobian(x, #(#rest),*)
                    }
                    fn time_derivative(&self, t: f64, x: &nalgebra::SVector<f64, #nl>) -> nalgebra::SVector<f64, #nl> {
                        let _ = (t, x);
                        #td
                    }
                }
            }
        }
    };
    let new = if np > 0 {
        quote! {
            impl System {
                /// The system at the parameters `params`.
                pub fn new(params: Params<f64>) -> System {
                    System { p: params.into() }
                }
            }
        }
    } else {
        quote! {
            impl System {
                /// The system (the model has no parameters).
                pub fn new() -> System {
                    System { p: nalgebra::SVector::zeros() }
                }
            }
        }
    };
    let sdoc = format!(
        " The `{}` model at fixed parameters `p` as `ẋ = f(t, x)` for pegdyn's integrators\n (exact right-hand side, Jacobian and time derivative from the generated functions).",
        l.model
    );
    quote! {
        #(#consts)*
        #[doc = #sdoc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct System {
            /// The parameter vector the functions take (from [`Params`]).
            pub p: nalgebra::SVector<f64, #npl>,
        }
        #new
        #body
    }
}
