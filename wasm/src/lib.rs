//! rodimpact's library as a WebAssembly module: the pages' one entry point, [`call`], with the
//! buffers it reads and writes. No wasm-bindgen: the page's loader (a few lines of JavaScript)
//! writes a UTF-8 request into memory given by [`alloc`], calls [`call`], and reads the
//! response at [`response_ptr`], [`response_len`] bytes long.
//!
//! A request is `{"name": "...", "request": {...}}`; the response is the JSON of
//! `rodimpact::app::pages::call` (an `{"error": ...}` object on a bad request).

use std::cell::RefCell;

thread_local! {
    /// The request buffer the page writes into, and the last response.
    static BUFFERS: RefCell<(Vec<u8>, Vec<u8>)> = const { RefCell::new((Vec::new(), Vec::new())) };
}

/// A buffer of `len` bytes for the request; its address (valid until the next `alloc`).
#[unsafe(no_mangle)]
pub extern "C" fn alloc(len: usize) -> *mut u8 {
    BUFFERS.with_borrow_mut(|(request, _)| {
        request.clear();
        request.resize(len, 0);
        request.as_mut_ptr()
    })
}

/// Answers the request in the buffer; the response's length in bytes.
#[unsafe(no_mangle)]
pub extern "C" fn call() -> usize {
    BUFFERS.with_borrow_mut(|(request, response)| {
        let text = String::from_utf8_lossy(request);
        *response = rodimpact::app::pages::call_json(&text).into_bytes();
        response.len()
    })
}

/// The address of the last response.
#[unsafe(no_mangle)]
pub extern "C" fn response_ptr() -> *const u8 {
    BUFFERS.with_borrow(|(_, response)| response.as_ptr())
}
