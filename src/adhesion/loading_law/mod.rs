//! Problem 2 with a loading law P1 = N(P2) (THEORY.md section 10; issue 12): the contact
//! [-a, b] grows at both ends. Built so far: [`kernel`], the increments on an off-centre contact
//! (the unit flat punch and its surface slopes on both sides, the left side checked against the
//! direct cot-kernel quadrature).

pub mod kernel;
