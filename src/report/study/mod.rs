//! The study document rendered: the Table 2 style table ([`table`]) and
//! its helpers ([`text`]), the summary CSV and the output files
//! ([`files`]), the Sobol table ([`sensitivity`]), the SVG plots ([`plot`])
//! and the charts a study has ([`charts`], with the reference values of
//! sigma of [`reference`]).

pub mod charts;
pub mod files;
pub mod labels;
pub mod plot;
pub mod reference;
pub mod sensitivity;
pub mod table;
pub mod text;
pub mod thermal;
pub mod verdict;
