//! Raw command-line arguments (clap). Numbers stay text here: they are read exactly in
//! [`super::config`].

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// periodic-contact: exact asymptotic series and high-precision solutions of the periodic contact
/// problem with friction, wear and adhesion (Soldatenkov 2013).
#[derive(Debug, Parser)]
#[command(name = "periodic-contact", version, about, long_about = None)]
pub struct RawArgs {
    /// What to do.
    #[command(subcommand)]
    pub command: RawCommand,
}

/// Output format of `series` (docs/theory.md section 16).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Plain text: a header per part, then one `[v^k] coefficient` line per non-zero coefficient.
    Text,
    /// JSON, one schema for every object: {"object", "parts": [{"object", "formula", "source",
    /// "variable", "order", "symbols", "sympy", "mathematica", "coefficients": [{"power", "text",
    /// "latex", "sympy"}]}]} (plus "notes"; "nu", "values" with adhesion --nu).
    Json,
    /// LaTeX as a paper prints it: `LHS &= c_0 + c_1 v + ... + O(v^{N+1})` in align*.
    Latex,
    /// A SymPy dict literal {"part": series + O(v**(N+1)), ...}: `sympy.sympify(text)` reads it.
    /// Names SymPy reads otherwise get a trailing underscore: S -> S_, Lambda -> Lambda_,
    /// lambda -> lambda_ (also E, I, N, O, Q, beta, gamma, pi, zeta).
    Sympy,
    /// A Mathematica association <|"part" -> series + O[v]^(N+1), ...|>; underscores dropped
    /// from names (rho_4 -> rho4).
    Mathematica,
}

/// Series objects the `series` command derives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ObjectName {
    /// Z(z) = z cot z, the kernel series [3.2].
    Kernel,
    /// Y(xh; lambda), the weight series [3.1].
    Weight,
    /// j_n(theta), the Jacobi moments [3.5].
    Jacobi,
    /// Problem 1 expansions in Lambda [3.7]-[3.12]: l_over_ls, rbar_minus_rbar_s, F_def, pi_j.
    Sliding,
    /// Problem 2 expansions [3.16]-[3.18]: A_n and c_n, exact in eps, B, S.
    Adhesion,
    /// Problem 2 under the linear loading law P1 = n P2 (issue 12): c/l, b/a, P2 and psi on both
    /// sides in lambda, in MPFR at given --nu and --ratio (30 digits, verified by a second run).
    LoadingLaw,
}

/// Output format of `solve`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SolveFormat {
    /// `key: value` lines (the JSON's keys joined by dots).
    Text,
    /// JSON with string values (keys: docs/theory.md section 14).
    Json,
}

/// Problems a scene template is written for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TemplateName {
    /// Problem 1: steady sliding with friction, adhesive friction and wear.
    Sliding,
    /// Problem 2: indentation with complete adhesion (with --law: under a loading law).
    Adhesion,
}

/// Punch shapes of a scene template: the names of the scene's `[punch] shape`, each with one
/// alias (issue 30: one canonical name per shape, the alias stated).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TemplateShape {
    /// g = k x^2 (alias: parabola).
    #[value(alias = "parabola")]
    Parabolic,
    /// g = D (1 - cos(2 pi x/L)), Problem 1 only (alias: sinusoid).
    #[value(alias = "sinusoid")]
    Sinusoidal,
    /// g = sum_j c_j x^j, Problem 2: even terms only (alias: poly).
    #[value(alias = "poly")]
    Polynomial,
    /// g = R - sqrt(R^2 - x^2) (alias: circle).
    #[value(alias = "circle")]
    Circular,
}

/// Solution methods.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodName {
    /// High precision (MPFR), verified by a second run.
    Mpfr,
    /// Fast f64.
    F64,
    /// Truncated exact series evaluated in MPFR (Problem 1).
    Series,
    /// Pade approximants of that series (Problem 1; docs/theory.md section 11).
    Pade,
    /// Problem 2 (complete adhesion): the member analytic at zero size, the paper's series continued
    /// past lambda_h (docs/theory.md section 11).
    Analytic,
}

/// Surface conventions of Problems 1 and 2 (docs/theory.md section 8).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ConventionName {
    /// The paper's equation [2.8] as it stands (its expansions are even in lambda).
    Paper,
    /// [2.8] plus K = (kappa P2 - 2 beta l tau0)/L: the surface closes over every period.
    Periodic,
}

/// Punch shapes of the series: the same names and aliases as [`TemplateShape`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ShapeName {
    /// g = k x^2 (alias: parabola).
    #[value(alias = "parabola")]
    Parabolic,
    /// g = D (1 - cos(2 pi x/L)) (alias: sinusoid).
    #[value(alias = "sinusoid")]
    Sinusoidal,
    /// g = sum_j c_j x^j, with --coefficients or --degree (alias: poly).
    #[value(alias = "poly")]
    Polynomial,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum RawCommand {
    /// Derive an exact series and print its coefficients (text, JSON, LaTeX, SymPy, Mathematica).
    #[command(long_about = SERIES_HELP)]
    Series {
        /// The object to derive.
        object: ObjectName,
        /// Keep every term through power N (for jacobi: j_0 .. j_N). At most: kernel, jacobi 2000;
        /// weight 80; sliding, adhesion, loading-law 24; a polynomial profile 16; adhesion --nu R
        /// 1000 (beyond 24 by its numerical route).
        #[arg(long, value_name = "N", allow_hyphen_values = true)]
        order: String,
        /// Substitute an exact rational for theta (e.g. 1/10), |theta| < 1/2.
        #[arg(long, value_name = "R", allow_hyphen_values = true)]
        theta: Option<String>,
        /// Substitute an exact rational for xh (weight, sliding), in [-1, 1].
        #[arg(long, value_name = "R", allow_hyphen_values = true)]
        xh: Option<String>,
        /// Substitute an exact rational for T = beta tau0/(E* k l_s) (sliding), T >= 0.
        #[arg(long = "T", value_name = "R", allow_hyphen_values = true)]
        t: Option<String>,
        /// Poisson's ratio in [0, 1/2] (adhesion: also print the coefficients' values to 30 digits;
        /// beyond order 24, or with --digits, the numerical route; loading-law: required).
        #[arg(long, value_name = "R", allow_hyphen_values = true)]
        nu: Option<String>,
        /// Digits of the numerical route of `adhesion --nu R` (default 30, at most 1000): the
        /// coefficients at nu in MPFR, verified by a second run, any order up to 1000.
        #[arg(long, value_name = "D", allow_hyphen_values = true)]
        digits: Option<String>,
        /// n = P1/P2 >= 0 of the linear loading law (loading-law, required).
        #[arg(long, value_name = "R", allow_hyphen_values = true)]
        ratio: Option<String>,
        /// Punch shape (sliding; default parabolic).
        #[arg(long, value_enum)]
        shape: Option<ShapeName>,
        /// Polynomial profile (sliding --shape polynomial, adhesion): exact coefficients in numpy
        /// order, index j multiplies x^j, e.g. 0,0,1,0,1/10 for x^2 + x^4/10; `?` keeps one symbolic.
        #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
        coefficients: Option<String>,
        /// Polynomial profile of degree D with every coefficient symbolic (adhesion: even ones).
        #[arg(long, value_name = "D", allow_hyphen_values = true)]
        degree: Option<String>,
        /// Substitute an exact rational for rbar_s, the single punch's centre over l_s (sliding
        /// --shape polynomial).
        #[arg(long = "rbar-s", value_name = "R", allow_hyphen_values = true)]
        rbar_s: Option<String>,
        /// Surface convention of the sliding expansions (docs/theory.md section 8; default paper:
        /// even powers of Lambda; periodic: odd powers too, symbols kappa = tan(pi theta), invpi = 1/pi).
        #[arg(long, value_enum)]
        convention: Option<ConventionName>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Also print the near-diagonal Pade approximants [L/M] of each part in w = var^2 (even
        /// series) or var, and their poles (text format; needs numerical coefficients: substitute
        /// every symbol, or give --nu for adhesion). docs/theory.md section 11.
        #[arg(long)]
        pade: bool,
    },
    /// Solve the problem a scene file describes and print the result with its verified accuracy.
    #[command(long_about = SOLVE_HELP)]
    Solve {
        /// Scene file (TOML; write one with `periodic-contact scene --template sliding`).
        scene: PathBuf,
        /// Digits requested: forces verified MPFR at this precision (overrides [output] digits and
        /// target_digits), an integer in [1, 1000].
        #[arg(long, value_name = "N", allow_hyphen_values = true)]
        digits: Option<String>,
        /// Method, forced (overrides [output] method and the choice by target_digits).
        #[arg(long, value_enum)]
        method: Option<MethodName>,
        /// Series order for --method series or pade (default 12), an integer in [0, 24].
        #[arg(long, value_name = "N", allow_hyphen_values = true)]
        order: Option<String>,
        /// Surface convention (overrides [problem] convention; default paper; docs/theory.md
        /// section 8): in Problem 2 `periodic` makes u periodic.
        #[arg(long, value_enum)]
        convention: Option<ConventionName>,
        /// Output format (default text).
        #[arg(long, value_enum)]
        format: Option<SolveFormat>,
        /// Same as --format json.
        #[arg(long)]
        json: bool,
    },
    /// Print a commented scene file (TOML) with every key, its meaning, unit and valid range: the
    /// table the scene parser checks against. Save it, edit the values, run `solve` on it.
    #[command(long_about = SCENE_HELP)]
    Scene {
        /// The problem.
        #[arg(long, value_enum)]
        template: TemplateName,
        /// The punch shape (adhesion: parabolic, polynomial or circular; --law: parabolic).
        #[arg(long, value_enum, default_value_t = TemplateShape::Parabolic)]
        shape: TemplateShape,
        /// Problem 2 under a loading law P1 = N(P2) (with --template adhesion).
        #[arg(long)]
        law: bool,
    },
    /// Write the report into a folder: the main job. Coefficient tables, method choice per scene,
    /// convergence orders, speed against accuracy, stability maps, load-size curves, paper vs
    /// periodic (Markdown, SVG charts with their CSV data, timings apart).
    Report {
        /// Output folder.
        #[arg(long, value_name = "DIR", default_value = "report")]
        out: PathBuf,
        /// Scene folder (every *.toml in it).
        #[arg(long, value_name = "DIR", default_value = "scenes")]
        scenes: PathBuf,
        /// Order of the coefficient tables.
        #[arg(long, value_name = "N", default_value = "12")]
        order: String,
        /// Small grids (seconds instead of minutes): the fixed set of the snapshot test.
        #[arg(long)]
        fast: bool,
        /// Threads for the report's sections and cells, an integer in [1, 256] (default: one per
        /// logical CPU, or RAYON_NUM_THREADS); 1 runs everything on one thread. report.md is the same
        /// for every value.
        #[arg(long, value_name = "N")]
        jobs: Option<String>,
    },
    /// Print a shell completion script, e.g. `periodic-contact completions bash >
    /// ~/.local/share/bash-completion/completions/periodic-contact`.
    Completions {
        /// The shell.
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// Print the man page (roff), e.g. `periodic-contact man > periodic-contact.1 && man
    /// ./periodic-contact.1`.
    Man,
    /// Measure each method's cost and accuracy and write the calibration table that the method
    /// choice reads (review and commit it; the binary compiles the committed table in).
    Calibrate {
        /// Output file.
        #[arg(long, value_name = "FILE", default_value = "calibration/methods.csv")]
        out: PathBuf,
    },
}

/// `solve --help`.
const SOLVE_HELP: &str = "Solve the problem a scene file describes and print the result with its accuracy.

Which method runs:
  --method M            forces M (mpfr: verified high precision; f64: fast, digits estimated by a
                        second run; series: the truncated exact series, Problem 1 only)
  --digits N            forces verified MPFR at N digits (also [output] digits)
  [output] method       forces a method from the scene
  [output] target_digits
                        the cheapest method predicted to meet it (calibration/methods.csv),
                        as the report chooses; the JSON's `choice` says which and why
  none of these         verified MPFR at 30 digits
Runs over about 2 s show progress on stderr.

Output: text (`key: value` lines) or --json (string values; every key: docs/theory.md
section 14). Exit codes: 0 answer, 2 invalid input (the message names the parameter, its value
and the valid range), 1 no solution, not physical or no convergence.

Examples:
  periodic-contact scene --template sliding > s.toml && periodic-contact solve s.toml --json
  periodic-contact solve s.toml --method f64
  periodic-contact solve s.toml --digits 50 --convention periodic";

/// `scene --help`.
const SCENE_HELP: &str = "Print a commented scene file (TOML) with every key the parser accepts for the
problem and shape: its meaning, unit and valid range, alternatives and optional keys commented out.
The text comes from the parser's own key table, so it cannot drift from what `solve` accepts.
Shapes (--shape, and `[punch] shape` in the scene): parabolic, sinusoidal, polynomial, circular;
--shape also takes the aliases parabola, sinusoid, poly, circle.

Numbers are exact: quote decimals and ratios (\"0.25\", \"1/3\", \"1e-3\"); unknown keys are errors.

Examples:
  periodic-contact scene --template sliding > sliding.toml
  periodic-contact scene --template sliding --shape sinusoidal
  periodic-contact scene --template adhesion --shape polynomial
  periodic-contact scene --template adhesion --law > law.toml
  periodic-contact solve sliding.toml --json";

/// `series --help`.
const SERIES_HELP: &str = "Derive an exact power series of the asymptotic analysis and print its coefficients.
Every symbol printed is defined in docs/theory.md section 12; the parts of each object in section 13.

Formats (--format):
  text         a header per part, then `[v^k] coefficient` lines (exact rationals / polynomials)
  json         {\"object\", \"parts\": [{\"object\", \"formula\", \"source\", \"variable\", \"order\",
               \"symbols\", \"sympy\", \"mathematica\", \"coefficients\": [{\"power\", \"text\", \"latex\",
               \"sympy\"}]}]}: one schema for every object
  latex        align* blocks as a paper prints them
  sympy        a dict literal {\"part\": series + O(v**(N+1))}; sympy.sympify(text) reads it back.
               Renamed so that sympify keeps them symbols: S -> S_, Lambda -> Lambda_,
               lambda -> lambda_ (and E, I, N, O, Q, beta, gamma, pi, zeta if they occur)
  mathematica  an association <|\"part\" -> series + O[v]^(N+1)|>; underscores dropped (rho_4 -> rho4)

Problem 2 (adhesion) has two routes:
  exact        symbols eps, B, S (docs/theory.md section 5), orders up to 24; with
               --nu R also each coefficient's value at nu to 30 digits
  numerical    with --nu R beyond order 24, or with --digits D at any order: C_P/pi, c_n and A_n at
               nu in MPFR (text or json), orders up to 1000, each coefficient printed with the
               digits a second run at higher precision verifies (--digits D asked, default 30).
               Where Re M_(2N+1) changes sign (nu = 0: N = 303) the exact coefficients have a
               pole in nu: the output says so and stops before it. The stress kernels h_N are
               not printed by either route: polynomials of degree 2N+1 in (xi, tau) with complex
               coefficients (the library's `adhesion_expansion` holds them exactly to order 24)

Examples:
  periodic-contact series kernel --order 12
  periodic-contact series sliding --order 8 --format sympy > sliding.py
  python3 -c \"import sympy; d = sympy.sympify(open('sliding.py').read()); print(d['l_over_ls'])\"
  periodic-contact series adhesion --order 6 --format latex
  periodic-contact series adhesion --order 200 --nu 3/10 --format json";
