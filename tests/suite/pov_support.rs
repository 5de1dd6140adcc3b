//! Running POV-Ray, the peer renderer, on the scenes `render -o scene.pov` writes.

/// POV-Ray's picture of `pov` at `width`×`height` with `options` (antialiasing, say), or `None`
/// where POV-Ray is not installed.
pub fn pov_ray(
    pov: &std::path::Path,
    (width, height): (u32, u32),
    options: &[&str],
) -> Option<std::path::PathBuf> {
    let png = pov.with_extension("png");
    let output = std::process::Command::new("povray")
        .args([format!("+W{width}"), format!("+H{height}")])
        .args(["-D", "-GA"])
        .args(options)
        .arg(format!("+O{}", png.display()))
        .arg(pov)
        .current_dir(pov.parent().unwrap())
        .output()
        .ok()?;
    let log = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "povray failed: {log}");
    Some(png)
}
