# stride_add_fmu is defined here (component packaging); see fmi/sdk.cmake for the SDK targets.
set_property(GLOBAL PROPERTY STRIDE_FMU_NAMES "")
