//! Running POV-Ray, the peer renderer, on the scenes `render -o scene.pov` writes.

/// POV-Ray's picture of `pov` at `width`×`height` with `options` (antialiasing, say). The tests
/// that call it are `#[ignore]`d with the reason; `bash .ci/run` installs POV-Ray and runs them.
pub fn pov_ray(
    pov: &std::path::Path,
    (width, height): (u32, u32),
    options: &[&str],
) -> std::path::PathBuf {
    let png = pov.with_extension("png");
    let output = std::process::Command::new("povray")
        .args([format!("+W{width}"), format!("+H{height}")])
        .args(["-D", "-GA"])
        .args(options)
        .arg(format!("+O{}", png.display()))
        .arg(pov)
        .current_dir(pov.parent().unwrap())
        .output()
        .expect("povray is not installed (bash .ci/run installs it)");
    let log = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "povray failed: {log}");
    png
}
