//! Wall time of the exact Problem 1 derivations (`sliding_expansion_with`) per shape, convention
//! and order: the numbers quoted in `src/report/runner.rs` (RunCache) and in the stability
//! section's choice of series orders. Orders as arguments (default 8 12):
//! `cargo run --release --example expansion_timing -- 8 12 16`.

use periodic_contact::asymptotics::sliding::{sliding_expansion_with, SlidingShape};
use periodic_contact::model::Convention;

fn main() {
    let orders: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let orders = if orders.is_empty() { vec![8, 12] } else { orders };
    for shape in [SlidingShape::Parabolic, SlidingShape::Sinusoidal] {
        for convention in [Convention::Paper, Convention::PeriodicSurface] {
            for &order in &orders {
                let t = std::time::Instant::now();
                match sliding_expansion_with(shape, order, convention) {
                    Ok(_) => {
                        println!("{shape:?}, {}, order {order}: {:.2} s", convention.name(), t.elapsed().as_secs_f64())
                    }
                    Err(e) => println!("{shape:?}, {}, order {order}: failed: {e}", convention.name()),
                }
            }
        }
    }
}
