//! The small language the claim files are written in: symbols and formulas, the symbolic scene,
//! visibly signed forms and certificate builders, and the pieces several claims share. A claim
//! file starts with `use crate::claims::dsl::*;`.
//!
//! Everything here is internal to the crate: the claims are the public surface, not the words
//! they are written in.

mod algebra;
mod equations;
mod forms;
mod impulse;
mod intuition;
mod motion;
mod oblique;
mod optimum;
mod peak;
mod scene;

pub(crate) use algebra::*;
pub(crate) use equations::*;
pub(crate) use forms::*;
pub(crate) use impulse::*;
pub(crate) use intuition::*;
pub(crate) use motion::*;
pub(crate) use oblique::*;
pub(crate) use optimum::*;
pub(crate) use peak::*;
pub(crate) use scene::*;

pub(crate) use super::certificate::{Expected, Integral, Limit, Positive};
pub(crate) use super::claim::BEYOND;
pub(crate) use super::export::{
    Check, Export, ExportLaw, Friction, Rod, Setting, Statement, StrikePoint,
};
pub(crate) use super::{
    Certificate, Decision, Entry, Formalised, Formula, Group, Paper, PosExpr, Relation,
};
