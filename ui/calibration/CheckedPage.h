// A wizard page whose "complete" state (which enables Next or Finish) is a
// function of the wizard's state, re-asked whenever the wizard calls
// recheck(): the pages of the calibration wizards are plain layouts around
// such a test, instead of one subclass per page.
#pragma once

#include <QWizardPage>

#include <functional>
#include <utility>

namespace tactiscope::ui {

class CheckedPage : public QWizardPage {
public:
    explicit CheckedPage(std::function<bool()> complete = {}, QWidget* parent = nullptr)
        : QWizardPage(parent),
          m_complete(std::move(complete))
    {
    }

    bool isComplete() const override { return m_complete ? m_complete() : QWizardPage::isComplete(); }
    void recheck() { emit completeChanged(); }

private:
    std::function<bool()> m_complete;
};

}  // namespace tactiscope::ui
