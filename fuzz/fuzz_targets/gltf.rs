#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| bumpwork_fuzz::gltf(data));
