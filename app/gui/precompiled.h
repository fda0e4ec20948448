// The widgets most of app/gui includes, precompiled after cmake/precompiled.h for the window's
// targets and the widget tests.
#pragma once

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <QWidget>
