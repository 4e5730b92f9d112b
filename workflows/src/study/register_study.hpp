// Signs `rockfdem sweep` and `rockfdem calibrate` up with the command line
// (the workflows library knows neither MPI nor NLopt).
#pragma once

namespace rockfdem::workflows::study {
void register_study_commands();
}
