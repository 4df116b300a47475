// Fixture: a part must not call core's detail:: functions.
#pragma once
namespace hider { inline int uses_core_detail() { return detail::core_private(); } }
