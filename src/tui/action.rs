//! Everything the user can ask of the workbench, independent of which key or mouse gesture asked.

/// One user request; the key map and the mouse both produce these, and the app applies them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Quits, unless an export is under way: then says once what quitting cancels.
    Quit,
    /// Quits whatever is under way (Ctrl-C).
    QuitNow,
    ToggleHelp,
    /// Esc with no overlay open: says how to quit.
    Back,
    /// The scene picker: a scene by name.
    OpenPicker,
    /// The scene at this place in the list shown, with its own state.
    GoToScene(usize),
    /// The message log: every message of the run.
    ToggleLog,
    NextScene,
    PreviousScene,
    /// Degrees of yaw and pitch.
    Orbit(f64, f64),
    /// Fractions of the orbit distance, right and up.
    Pan(f64, f64),
    /// Distance factor: below 1 moves closer.
    Zoom(f64),
    ResetCamera,
    /// Degrees of azimuth and elevation.
    MoveLight(f64, f64),
    /// The lights back where the scene file puts them.
    ResetLights,
    /// Shadows on or off (the scene file's `shadows`, until it is saved or reloaded).
    ToggleShadows,
    ToggleDisplacement,
    /// Every material value changed with the keys back to the file's (patterns, parameters,
    /// strengths).
    DropLiveValues,
    NextViewMode,
    PreviousViewMode,
    NextQuality,
    NextGlyphs,
    NextColors,
    /// The object whose material the pattern, texture and bump keys edit.
    NextObject,
    NextPattern,
    PreviousPattern,
    NextTexture,
    PreviousTexture,
    /// Bump strength factor.
    ScaleBump(f32),
    InvertBump,
    /// Select the next (+1) or previous (−1) pattern parameter (the bump's, then the texture's).
    SelectParam(i32),
    /// Steps of the selected parameter: a fiftieth of its range, or a factor of 1.05 for a
    /// parameter whose range spans a factor of 20 or more from above 0 (a period, a size).
    AdjustParam(f32),
    /// Opens or closes the parameter panel.
    TogglePanel,
    /// Select the parameter in this row of the panel (a click).
    SelectParamAt(usize),
    /// Select the parameter in this row of the panel and move it by steps (the wheel over it).
    AdjustParamAt(usize, f32),
    /// Sets the parameter in this row of the panel to a value typed (checked by the panel).
    SetParam(usize, f32),
    TogglePause,
    StepClock,
    Export,
    /// The view as a new scene file in the export directory.
    SaveScene,
}
