//! A global allocator that counts the allocations **of the calling thread**, for the tests that
//! prove a hot loop allocates nothing.
//!
//! The count is per thread: the test harness runs other tests (and its own bookkeeping) on other
//! threads at the same time, and their allocations must not land in the counting window. A
//! process-wide counter made these tests fail by chance on a busy machine.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

pub struct Counting;

thread_local! {
    // `const` initialisation: reading it never allocates (no lazy set-up, no destructor).
    static ALLOCATIONS: Cell<u64> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        // `try_with` fails only while the thread is being torn down; nothing is counted then.
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        System.alloc(l)
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        System.dealloc(p, l)
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        System.realloc(p, l, new_size)
    }
}

/// Allocations (and reallocations) made so far by the calling thread.
pub fn allocations_on_this_thread() -> u64 {
    ALLOCATIONS.with(|c| c.get())
}

/// Run `f` and return its result with the number of allocations it made on this thread.
pub fn count_allocations<T>(f: impl FnOnce() -> T) -> (T, u64) {
    let before = allocations_on_this_thread();
    let out = f();
    (out, allocations_on_this_thread() - before)
}

#[global_allocator]
static COUNTING: Counting = Counting;
